#include "gpu/knot_tables.hpp"

#include <QOpenGLShaderProgram>
#include <algorithm>
#include <stdexcept>
#include <string>

#include "gpu/gl_helpers.hpp"
#include "gpu/wood_program.hpp"

namespace kerf {
namespace {

constexpr int kRowLength = 4096;       // long 1D lists are wrapped into rows of this many texels
constexpr int kNoiseKnotsPerRow = 32;  // as in shaders/knots.glsl

enum Table { kPith, kRadii, kSkeletons, kKnotInfo, kKnotNoise, kColors, kKnotList };

// Pads a wrapped list to whole rows (at least one texel).
template <typename T>
int wrapRows(std::vector<T>& values, int componentsPerTexel) {
  const std::size_t texels = std::max<std::size_t>(values.size() / componentsPerTexel, 1);
  const int rows = static_cast<int>((texels + kRowLength - 1) / kRowLength);
  values.resize(static_cast<std::size_t>(rows) * kRowLength * componentsPerTexel, T{});
  return rows;
}

}  // namespace

void uploadTexelTable(unsigned texture, int unit, int internalFormat, int width, int height, unsigned format,
                      unsigned type, const void* data) {
  QOpenGLExtraFunctions* f = currentGl();
  GLint maxSize = 0;
  f->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (width > maxSize || height > maxSize) {
    throw std::runtime_error("knot tables: a " + std::to_string(width) + " x " + std::to_string(height) +
                             " table exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize));
  }
  f->glActiveTexture(GL_TEXTURE0 + unit);
  f->glBindTexture(GL_TEXTURE_2D, texture);
  const PackedRowsUpload packed;
  f->glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, type, data);
  f->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  f->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  f->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
}

KnotTables::KnotTables() {
  currentGl()->glGenTextures(kTextureCount, textures_);
}

KnotTables::~KnotTables() {
  if (QOpenGLContext::currentContext()) currentGl()->glDeleteTextures(kTextureCount, textures_);
}

void KnotTables::uploadLog(const KnotField& field, const WoodColorMap& colors, std::span<const int> knots,
                           int unit) {
  const LogModel& log = field.log();
  const Stem& stem = log.stem;
  std::vector<float> pith(static_cast<std::size_t>(stem.slices()) * 2);
  for (int i = 0; i < stem.slices(); ++i) pith[2 * i] = stem.pith[i].x, pith[2 * i + 1] = stem.pith[i].y;

  const int count = static_cast<int>(knots.size());
  int maxSamples = 1;
  for (const int k : knots) maxSamples = std::max(maxSamples, log.knots[k].samples());
  const int knotRows = std::max(count, 1);
  std::vector<float> tables(static_cast<std::size_t>(maxSamples) * knotRows * 2, 0.0f);
  std::vector<float> info(static_cast<std::size_t>(knotRows) * 4, 0.0f);
  constexpr int kAngles = KnotField::kNoiseTableAngles, kTimes = KnotField::kNoiseTableTimes;
  constexpr std::size_t kCells = static_cast<std::size_t>(kAngles) * kTimes;
  // The noise tables side by side, kNoiseKnotsPerRow knots of kAngles x kTimes per texture row.
  const int noiseRows = (knotRows + kNoiseKnotsPerRow - 1) / kNoiseKnotsPerRow;
  const std::size_t noiseWidth = static_cast<std::size_t>(kNoiseKnotsPerRow) * kAngles;
  std::vector<float> noise(noiseWidth * noiseRows * kTimes * 2, 0.0f);
  const std::vector<float>& speedNoise = field.speedNoiseTable();
  const std::vector<float>& outlineNoise = field.outlineNoiseTable();
  if (speedNoise.size() != kCells * log.knots.size() || outlineNoise.size() != speedNoise.size()) {
    throw std::logic_error("knot tables: unexpected knot noise table size");
  }
  for (int i = 0; i < count; ++i) {
    const Knot& knot = log.knots[knots[i]];
    for (int j = 0; j < knot.samples(); ++j) {
      tables[(static_cast<std::size_t>(i) * maxSamples + j) * 2] = knot.heights[j];
      tables[(static_cast<std::size_t>(i) * maxSamples + j) * 2 + 1] = knot.azimuths[j];
    }
    info[4 * i] = knot.distanceStep;
    info[4 * i + 1] = static_cast<float>(knot.samples());
    info[4 * i + 2] = knot.deathDistance;
    info[4 * i + 3] = static_cast<float>(knots[i]);  // the log's index: the seed of the knot's checks
    const std::size_t from = static_cast<std::size_t>(knots[i]) * kCells;
    for (int t = 0; t < kTimes; ++t) {
      const std::size_t row = static_cast<std::size_t>(i / kNoiseKnotsPerRow) * kTimes + t;
      const std::size_t column = static_cast<std::size_t>(i % kNoiseKnotsPerRow) * kAngles;
      for (int a = 0; a < kAngles; ++a) {
        const std::size_t at = (row * noiseWidth + column + a) * 2;
        noise[at] = speedNoise[from + static_cast<std::size_t>(t) * kAngles + a];
        noise[at + 1] = outlineNoise[from + static_cast<std::size_t>(t) * kAngles + a];
      }
    }
  }
  std::vector<float> colorTexels;
  colorTexels.reserve(colors.colors.size() * 3);
  for (const glm::vec3& c : colors.colors) colorTexels.insert(colorTexels.end(), {c.x, c.y, c.z});
  const int colorRows = wrapRows(colorTexels, 3);

  uploadTexelTable(textures_[kPith], unit, GL_RG32F, stem.slices(), 1, GL_RG, GL_FLOAT, pith.data());
  uploadTexelTable(textures_[kRadii], unit, GL_R32F, stem.azimuths, stem.slices(), GL_RED, GL_FLOAT,
                   stem.radii.data());
  uploadTexelTable(textures_[kSkeletons], unit, GL_RG32F, maxSamples, knotRows, GL_RG, GL_FLOAT,
                   tables.data());
  uploadTexelTable(textures_[kKnotInfo], unit, GL_RGBA32F, knotRows, 1, GL_RGBA, GL_FLOAT, info.data());
  uploadTexelTable(textures_[kKnotNoise], unit, GL_RG32F, static_cast<int>(noiseWidth), kTimes * noiseRows,
                   GL_RG, GL_FLOAT, noise.data());
  uploadTexelTable(textures_[kColors], unit, GL_RGB32F, kRowLength, colorRows, GL_RGB, GL_FLOAT,
                   colorTexels.data());
  settings_ = field.settings();
  heightStep_ = stem.heightStep;
  slices_ = stem.slices();
  azimuths_ = stem.azimuths;
  colorCount_ = static_cast<int>(colors.colors.size());
  knotCount_ = count;
}

void KnotTables::uploadKnotList(std::vector<int> list, int unit) {
  const int rows = wrapRows(list, 1);
  uploadTexelTable(textures_[kKnotList], unit, GL_R32I, kRowLength, rows, GL_RED_INTEGER, GL_INT,
                   list.data());
}

void KnotTables::bind(QOpenGLShaderProgram& p, int firstUnit) const {
  QOpenGLExtraFunctions* f = currentGl();
  static const char* const samplers[kTextureCount] = {"u_pith",      "u_radii",  "u_knotTables", "u_knotInfo",
                                                      "u_knotNoise", "u_colors", "u_tileKnots"};
  for (int t = 0; t < kTextureCount; ++t) {
    f->glActiveTexture(GL_TEXTURE0 + firstUnit + t);
    f->glBindTexture(GL_TEXTURE_2D, textures_[t]);
    p.setUniformValue(samplers[t], firstUnit + t);
  }
  f->glActiveTexture(GL_TEXTURE0);
  p.setUniformValue("u_heightStep", heightStep_);
  p.setUniformValue("u_slices", slices_);
  p.setUniformValue("u_azimuths", azimuths_);
  p.setUniformValue("u_colorCount", colorCount_);
  p.setUniformValue("u_colorRowLength", kRowLength);
  p.setUniformValue("u_tileListRow", kRowLength);
  // The schema's knot parameters (P.knot*), from the field's settings rather than the document's.
  settings_.forEachParameter([&p](const ParamSpec& spec, std::span<const float> value) {
    WoodProgram::setParameter(p, spec, value);
  });
}

}  // namespace kerf
