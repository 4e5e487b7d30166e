#include "fit/colour_fit.hpp"

#include <ceres/ceres.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>
#include <map>
#include <tuple>
#include <vector>

#include "fit/ceres_progress.hpp"
#include "fit/colour_bins.hpp"
#include "render/wood_model.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

namespace kerf {

namespace {

using colour_fit::Bin;
using colour_fit::BinCost;
using colour_fit::ColourConstants;
using colour_fit::ColourModel;
using colour_fit::kProfileSize;
using colour_fit::Sample;

// Beer's law: latewood, pores and every darker part of the wood hold more of one pigment, so the log
// ratio log(L/E) per channel points along that pigment's absorption, which is the species'. The per-bin
// statistics alone leave the channels free: fits that darkened green most turned the pores purple, and
// one that darkened only green and blue made a held-out face red and green. This penalises the part of
// log(L/E) off the pigment direction the photos show (pigmentDirectionOf).
struct PigmentHuePrior {
  double weight;
  glm::dvec3 direction;  // unit
  template <class T>
  bool operator()(const T* early, const T* late, T* residual) const {
    using std::log;
    T ratio[3];
    for (int c = 0; c < 3; ++c) ratio[c] = log(late[c] / early[c]);
    const T along = ratio[0] * direction.x + ratio[1] * direction.y + ratio[2] * direction.z;
    for (int c = 0; c < 3; ++c) residual[c] = weight * (ratio[c] - along * direction[c]);
    return true;
  }
};

// The pigment's direction in log colour, as the photos show it: the main axis of the points' log colours
// (light and dark wood differ mostly by how much pigment they hold), pointing from light to dark.
glm::dvec3 pigmentDirectionOf(const std::vector<Sample>& samples) {
  glm::dvec3 mean(0.0);
  for (const Sample& s : samples)
    mean += glm::log(glm::max(glm::dvec3(s.target[0], s.target[1], s.target[2]), glm::dvec3(1e-3)));
  mean /= double(samples.size());
  glm::dmat3 covariance(0.0);
  for (const Sample& s : samples) {
    const glm::dvec3 d =
        glm::log(glm::max(glm::dvec3(s.target[0], s.target[1], s.target[2]), glm::dvec3(1e-3))) - mean;
    covariance += glm::outerProduct(d, d);
  }
  glm::dvec3 axis = glm::normalize(glm::dvec3(-1.0));
  for (int i = 0; i < 50; ++i) {  // power iteration: the covariance's largest eigenvector
    const glm::dvec3 next = covariance * axis;
    if (glm::length(next) < 1e-12) break;
    axis = glm::normalize(next);
  }
  return axis.x + axis.y + axis.z > 0 ? -axis : axis;
}

// Heartwood and sapwood colours stay together unless the photos show both: a block all in its sapwood
// (CN03) says nothing of its heartwood, which a held-out face or a cut may still reach.
struct HeartSapPrior {
  double weight;
  template <class T>
  bool operator()(const T* heart, const T* sap, T* residual) const {
    for (int c = 0; c < 3; ++c) residual[c] = weight * (heart[c] - sap[c]);
    return true;
  }
};

// Keeps the ring profile smooth from knot to knot (periodic second differences) and small: the photos
// decide its shape, not the noise of single points.
struct ProfilePrior {
  double smooth, small;
  template <class T>
  bool operator()(const T* profile, T* residual) const {  // profile[8] and [9] (season, pores) are free
    for (int k = 0; k < 8; ++k) {
      residual[k] = smooth * (profile[(k + 7) % 8] - 2.0 * profile[k] + profile[(k + 1) % 8]);
      residual[8 + k] = small * profile[k];
    }
    return true;
  }
};

struct PoreDarknessPrior {
  double weight, start;
  template <class T>
  bool operator()(const T* profile, T* residual) const {
    using std::log;
    residual[0] = weight * log((profile[9] + 0.1) / (start + 0.1));
    return true;
  }
};

struct TintPrior {
  double weight;
  template <class T>
  bool operator()(const T* tint, T* residual) const {
    for (int c = 0; c < 3; ++c) residual[c] = weight * (tint[c] - T(1));
    return true;
  }
};

glm::dvec3 toD(glm::vec3 v) {
  return glm::dvec3(v);
}

double luminance(const double* c) {
  return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2];
}

// A start for the colours and the ring profile from per year-phase statistics (issue 16): the photos'
// mean colour at each of the profile's eight knots (each face divided by its own mean, so lighting
// differences between faces drop out), its lightest and darkest phase as earlywood and latewood colour,
// and the profile that puts every phase at its own shade by Beer's law. Means over whole faces are
// hardly touched by a fraction of a millimetre of misregistration, so the ring keeps its contrast, and
// the point-by-point fit that follows starts from the right shading instead of collapsing to one colour.
bool ringProfileStart(const std::vector<Sample>& samples, double* early, double* late, double* profile) {
  double faceMean[6][3] = {}, faceCount[6] = {};
  for (const Sample& s : samples) {
    for (int c = 0; c < 3; ++c) faceMean[s.face][c] += s.target[c];
    faceCount[s.face] += 1;
  }
  double overall[3] = {0, 0, 0}, faces = 0;
  for (int f = 0; f < 6; ++f)
    if (faceCount[f] > 0) {
      for (int c = 0; c < 3; ++c) overall[c] += (faceMean[f][c] /= faceCount[f]);
      faces += 1;
    }
  for (int c = 0; c < 3; ++c) overall[c] /= faces;
  double colour[8][3] = {}, pigment[8] = {}, count[8] = {};
  for (const Sample& s : samples) {
    const int knot = (s.profileKnot + (s.profileWeight[2] > s.profileWeight[1] ? 1 : 0)) % 8;  // nearest
    for (int c = 0; c < 3; ++c)
      colour[knot][c] += s.target[c] / std::max(faceMean[s.face][c], 1e-3) * overall[c];
    pigment[knot] += s.pigment;
    count[knot] += 1;
  }
  int lightest = -1, darkest = -1;
  for (int k = 0; k < 8; ++k) {
    if (count[k] < 20) return false;  // too few points at some phase (a tiny or ring-less sample)
    for (int c = 0; c < 3; ++c) colour[k][c] /= count[k];
    pigment[k] /= count[k];
    if (lightest < 0 || luminance(colour[k]) > luminance(colour[lightest])) lightest = k;
    if (darkest < 0 || luminance(colour[k]) < luminance(colour[darkest])) darkest = k;
  }
  const double light = luminance(colour[lightest]), dark = luminance(colour[darkest]);
  if (light - dark < 0.01 * light) return false;  // no ring shading to speak of
  for (int c = 0; c < 3; ++c) early[c] = colour[lightest][c], late[c] = colour[darkest][c];
  for (int k = 0; k < 8; ++k)
    profile[k] = std::log(luminance(colour[k]) / light) / std::log(dark / light) - pigment[k];
  profile[8] = 0;  // the shading starts as the profile's alone; the fit adds the season's where it helps
  return true;
}

}  // namespace

ColourFitResult fitColours(const Block& block, const WoodParameters& params, const GrowthRates& rates,
                           const std::array<Image, 6>& photos, const ColourFitOptions& options,
                           const Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  if (std::all_of(photos.begin(), photos.end(), [](const Image& i) { return i.empty(); }))
    throw InputError("no face photo to fit the colours to");
  const WoodModel model(block, params, rates);
  const int n = std::max(2, options.samplesPerSide);

  // Samples: an n x n grid of points per face; the photo's colour over a window of about 0.15 mm around
  // each (a photo pixel of the usual 256 px per 40 mm) and the model at the same point.
  const WoodMaterial& material = model.material();
  std::vector<Sample> samples;
  for (FaceId face : kAllFaces) {
    const Image& photo = photos[faceIndex(face)];
    if (photo.empty()) continue;
    if (photo.channels < 3)
      throw InputError("the colour fit needs colour photos (face " + std::string(1, faceLetter(face)) +
                       " has one channel)");
    const int window = std::max(1, static_cast<int>(std::lround(photo.width / 256.0)));
    const std::size_t first = samples.size();
    samples.resize(first + static_cast<std::size_t>(n) * n);
    parallelRows(
        n,
        [&](int row) {
          for (int col = 0; col < n; ++col) {
            Sample& s = samples[first + static_cast<std::size_t>(row) * n + col];
            s.face = faceIndex(face);
            const glm::vec2 at((col + 0.5f) * photo.width / n, (row + 0.5f) * photo.height / n);
            const int x0 = std::clamp(static_cast<int>(at.x) - window / 2, 0, photo.width - window);
            const int y0 = std::clamp(static_cast<int>(at.y) - window / 2, 0, photo.height - window);
            double sum[3] = {0, 0, 0};
            for (int y = y0; y < y0 + window; ++y)
              for (int x = x0; x < x0 + window; ++x)
                for (int c = 0; c < 3; ++c) sum[c] += photo.pixel(x, y)[c];
            for (int c = 0; c < 3; ++c) s.target[c] = sum[c] / (double(window) * window);
            const WoodSample w = model.evaluate(block.imageToBlock(face, at, {photo.width, photo.height}));
            glm::vec4 weights;
            s.profileKnot = material.ringProfileCell(w.year, weights);
            for (int i = 0; i < 4; ++i) s.profileWeight[i] = weights[i];
            s.pigment = w.pigment - material.ringProfile(w.year) - params.seasonShading * w.latewood;
            s.season = w.latewood;
            s.year = w.year, s.ray = w.ray, s.phase = material.yearPhase(w.year);
            for (int i = 0; i < 9; ++i) {
              const glm::vec2 sub(x0 + (i % 3 + 0.5f) * window / 3.0f, y0 + (i / 3 + 0.5f) * window / 3.0f);
              s.pore[i] = model.evaluate(block.imageToBlock(face, sub, {photo.width, photo.height})).pore;
            }
          }
        },
        progress);
  }
  progress.set(0.3);

  double early[3], late[3], sapEarly[3], sapLate[3], sap[2], tint[6][3];
  const auto load = [](const glm::vec3& v, double* out) { out[0] = v.x, out[1] = v.y, out[2] = v.z; };
  load(params.earlywoodColor, early), load(params.latewoodColor, late);
  load(params.sapwoodEarlywoodColor, sapEarly), load(params.sapwoodLatewoodColor, sapLate);
  sap[0] = params.sapwoodStart, sap[1] = params.sapwoodTransition;
  glm::vec3 WoodParameters::*const tints[6] = {&WoodParameters::faceTintA, &WoodParameters::faceTintB,
                                               &WoodParameters::faceTintC, &WoodParameters::faceTintD,
                                               &WoodParameters::faceTintE, &WoodParameters::faceTintF};
  for (int f = 0; f < 6; ++f) load(params.*tints[f], tint[f]);
  float WoodParameters::*const knots[8] = {&WoodParameters::ringProfile0, &WoodParameters::ringProfile1,
                                           &WoodParameters::ringProfile2, &WoodParameters::ringProfile3,
                                           &WoodParameters::ringProfile4, &WoodParameters::ringProfile5,
                                           &WoodParameters::ringProfile6, &WoodParameters::ringProfile7};
  double profile[kProfileSize];
  for (int k = 0; k < 8; ++k) profile[k] = params.*knots[k];
  profile[8] = params.seasonShading;
  profile[9] = params.poreDarkness;

  const glm::dvec3 rayColor = toD(params.rayColor);
  // The pores' shadow takes the hue of the photos' light-to-dark axis, as their latewood pigment does.
  const glm::dvec3 direction = pigmentDirectionOf(samples);
  glm::dvec3 shadowHue = toD(params.poreShadowHue);
  if (glm::all(glm::lessThan(direction, glm::dvec3(0.0))))
    shadowHue = glm::max(-direction / std::max({-direction.x, -direction.y, -direction.z}), glm::dvec3(0.05));
  const glm::dvec3 poreHue =
      glm::max(shadowHue, glm::dvec3(1e-3)) / ((shadowHue.x + shadowHue.y + shadowHue.z) / 3.0);
  const ColourConstants constants{rayColor, params.rayOpacity, poreHue};
  const auto l1PerFace = [&](std::array<double, 6>& out) {
    std::array<double, 6> count{};
    out.fill(0.0);
    for (const Sample& s : samples) {
      double colour[3];
      ColourModel{&s, &constants}(early, late, sapEarly, sapLate, sap, tint[s.face], profile, colour);
      for (int c = 0; c < 3; ++c)
        out[s.face] += std::abs(std::clamp(colour[c], 0.0, 1.0) - s.target[c]) / 3.0;
      count[s.face] += 1;
    }
    for (int f = 0; f < 6; ++f) out[f] = count[f] > 0 ? out[f] / count[f] : 0.0;
  };
  ColourFitResult result;
  l1PerFace(result.l1Before);
  if (options.fitRingProfile && ringProfileStart(samples, early, late, profile))
    for (int c = 0; c < 3; ++c) sapEarly[c] = early[c], sapLate[c] = late[c];

  ceres::Problem problem;
  std::map<std::tuple<int, int, int>, Bin> bins;  // (face, sixteenth of the year, 5-year band)
  for (const Sample& s : samples) {
    Bin& bin = bins[{s.face, std::min(15, static_cast<int>(16 * s.phase)),
                     static_cast<int>(std::floor(s.year / 5.0))}];
    bin.members.push_back(&s);
    for (int c = 0; c < 3; ++c) bin.target[c] += s.target[c];
    const double y = luminance(s.target);
    bin.targetSpread += y * y;  // the sum of squares until divided below
  }
  for (auto& [key, bin] : bins) {
    if (bin.members.size() < 8) continue;  // a sliver of a year at a face's edge: too noisy to weigh
    const double n = static_cast<double>(bin.members.size());
    for (double& t : bin.target) t /= n;
    bin.targetSpread =
        std::sqrt(std::max(0.0, bin.targetSpread / n - luminance(bin.target) * luminance(bin.target)));
    bin.constants = constants, bin.spreadWeight = options.spreadWeight;
    bin.weight = std::sqrt(n / static_cast<double>(samples.size()));
    const int face = std::get<0>(key);
    problem.AddResidualBlock(new BinCost(std::move(bin)), nullptr, early, late, sapEarly, sapLate, sap,
                             tint[face], profile);
  }
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<ProfilePrior, 16, kProfileSize>(
                               new ProfilePrior{options.profileSmoothness, options.profileSmallness}),
                           nullptr, profile);
  for (int k = 0; k < 8; ++k) {
    problem.SetParameterLowerBound(profile, k, -10.0);
    problem.SetParameterUpperBound(profile, k, 10.0);
  }
  problem.SetParameterLowerBound(profile, 8, 0.0);
  problem.SetParameterUpperBound(profile, 8, 3.0);
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PoreDarknessPrior, 1, kProfileSize>(
                               new PoreDarknessPrior{options.poreDarknessWeight, params.poreDarkness}),
                           nullptr, profile);
  problem.SetParameterLowerBound(profile, 9, 0.0);  // pores.darkness's schema range
  problem.SetParameterUpperBound(profile, 9, 20.0);
  for (const auto& [heart, sapColour] : {std::pair{early, sapEarly}, std::pair{late, sapLate}})
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<HeartSapPrior, 3, 3, 3>(new HeartSapPrior{options.heartSapWeight}),
        nullptr, heart, sapColour);
  const std::pair<double*, double*> pairs[2] = {{early, late}, {sapEarly, sapLate}};
  const glm::dvec3 directions[2] = {direction, direction};
  for (int i = 0; i < 2; ++i)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PigmentHuePrior, 3, 3, 3>(
                                 new PigmentHuePrior{options.pigmentHueWeight, directions[i]}),
                             nullptr, pairs[i].first, pairs[i].second);
  if (!options.fitRingProfile) problem.SetParameterBlockConstant(profile);
  for (int f = 0; f < 6; ++f) {
    if (photos[f].empty()) continue;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<TintPrior, 3, 3>(new TintPrior{std::sqrt(options.tintWeight / 18.0)}),
        nullptr, tint[f]);
    for (int c = 0; c < 3; ++c) {
      problem.SetParameterLowerBound(tint[f], c, 0.0);
      problem.SetParameterUpperBound(tint[f], c, 4.0);
    }
  }
  for (double* colour : {early, late, sapEarly, sapLate})
    for (int c = 0; c < 3; ++c) {
      problem.SetParameterLowerBound(colour, c, 0.005);
      problem.SetParameterUpperBound(colour, c, 1.0);
    }
  problem.SetParameterLowerBound(sap, 0, 0.0);
  problem.SetParameterUpperBound(sap, 0, 2000.0);
  problem.SetParameterLowerBound(sap, 1, 0.01);
  problem.SetParameterUpperBound(sap, 1, 200.0);
  if (!options.fitSapwood) problem.SetParameterBlockConstant(sap);

  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;  // 40 parameters
  so.max_num_iterations = options.maxIterations;
  so.num_threads = 1;  // deterministic
  CeresProgress callback(progress, options.maxIterations, 0.3, 1.0);
  so.callbacks.push_back(&callback);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  progress.throwIfCancelled();

  l1PerFace(result.l1After);
  WoodParameters out = params;
  const auto store = [](const double* v) { return glm::vec3(v[0], v[1], v[2]); };
  out.earlywoodColor = store(early), out.latewoodColor = store(late);
  out.sapwoodEarlywoodColor = store(sapEarly), out.sapwoodLatewoodColor = store(sapLate);
  out.sapwoodStart = static_cast<float>(sap[0]), out.sapwoodTransition = static_cast<float>(sap[1]);
  for (int f = 0; f < 6; ++f) out.*tints[f] = store(tint[f]);
  for (int k = 0; k < 8; ++k) out.*knots[k] = static_cast<float>(profile[k]);
  out.seasonShading = static_cast<float>(profile[8]);
  out.poreDarkness = static_cast<float>(profile[9]);
  out.poreShadowHue = glm::vec3(shadowHue);
  validate(out);
  result.params = out;
  result.samples = static_cast<int>(samples.size());
  result.iterations = static_cast<int>(summary.iterations.size());
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace kerf
