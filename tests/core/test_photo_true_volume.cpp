// The photo-true colour volume (issue 17, appearance/photo_true_volume.hpp) on the demo block rendered by
// Kerf's own model, whose field and colours are known exactly (as in test_photo_true.cpp): its slices
// across the fibres resemble the model's own wood there, a slice along the fibres shows the grain the
// model shows, consecutive slices continue each other (pores are tubes, not noise from slice to slice),
// and the exported volume holds exactly the volume's colours and says whose they are.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stop_token>

#include "appearance/photo_true_appearance.hpp"
#include "appearance/photo_true_source.hpp"
#include "demo/demo_block.hpp"
#include "export/export_job.hpp"
#include "io/nrrd_writer.hpp"
#include "io/project.hpp"
#include "photo_true_measures.hpp"
#include "render/renderers.hpp"
#include "render/wood_model.hpp"
#include "test_files.hpp"
#include "util/error.hpp"
#include "util/parallel.hpp"

using namespace kerf;
using namespace kerf::testing;
namespace fs = std::filesystem;

namespace {

constexpr int kSide = 64;  // photo pixels per face: 1.6 px/mm on the 40 mm demo cube

struct VolumeFixture {
  Project project = demoProject(7);
  std::unique_ptr<WoodModel> model;
  std::array<Image, 6> photos;
  PhotoTrueOptions options;
  std::unique_ptr<PhotoTrueAppearance> appearance;
  PhotoTrueVolume volume;
  VolumeFixture() {
    model = std::make_unique<WoodModel>(project);
    for (FaceId face : kAllFaces) photos[faceIndex(face)] = renderFace(*model, face, {kSide, kSide}, 2);
    options.synthesis.passes = 2;
    appearance = std::make_unique<PhotoTrueAppearance>(*model, photos, FaceSet{}, options);
    volume = appearance->renderVolume({kSide, kSide, kSide});
  }
};

const VolumeFixture& fixture() {
  static const VolumeFixture f;
  return f;
}

// The plane of samples with index `k` along `axis`, as an image (x: the lower other axis, y: the higher),
// each pixel's colour from colourOf(voxel).
template <class ColourOf>
Image slice(const PhotoTrueVolume& v, int axis, int k, ColourOf colourOf) {
  const int u = axis == 0 ? 1 : 0, w = axis == 2 ? 1 : 2;
  Image out(v.size[u], v.size[w], 3);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      glm::ivec3 voxel(0);
      voxel[u] = x, voxel[w] = y, voxel[axis] = k;
      const glm::vec3 c = colourOf(voxel);
      for (int ch = 0; ch < 3; ++ch) out.pixel(x, y)[ch] = c[ch];
    }
  return out;
}

// From the volume, or from the model itself at the same points (the truth).
Image volumeSlice(const PhotoTrueVolume& v, int axis, int k) {
  return slice(v, axis, k, [&](glm::ivec3 voxel) {
    const std::uint8_t* c = &v.rgb[((std::size_t(voxel.z) * v.size.y + voxel.y) * v.size.x + voxel.x) * 3];
    return glm::vec3(c[0], c[1], c[2]) / 255.0f;
  });
}

Image modelSlice(const WoodModel& model, const PhotoTrueVolume& v, int axis, int k) {
  return slice(v, axis, k, [&](glm::ivec3 voxel) {
    return model.evaluate(v.origin + glm::vec3(voxel) * v.spacing).color;
  });
}

}  // namespace

TEST(PhotoTrueVolume, SlicesAcrossTheFibresResembleTheWoodThere) {
  const VolumeFixture& f = fixture();
  const PhotoTrueVolume& v = f.volume;
  ASSERT_EQ(v.size, glm::ivec3(kSide));  // the photos' resolution: 1.6 px/mm over 40 mm
  // Stacked along the axis nearest to the fibres (the demo block's pith runs along one of the axes).
  const glm::vec3 fibre = glm::abs(f.model->material().locate({0, 0, 0}, true).fiberDirection);
  EXPECT_EQ(v.sliceAxis, fibre.x > std::max(fibre.y, fibre.z) ? 0 : (fibre.y > fibre.z ? 1 : 2));
  for (int k : {kSide / 4, kSide / 2, 3 * kSide / 4}) {
    const Image slice = volumeSlice(v, v.sliceAxis, k), truth = modelSlice(*f.model, v, v.sliceAxis, k);
    const double corr = bandPassCorrelation(slice, truth),
                 unrelated = bandPassCorrelation(rotatedQuarter(truth), truth);
    const double orient = orientationAgreement(slice, truth);
    std::printf("slice %d across the fibres: corr %.3f (unrelated %.3f), orient %.3f\n", k, corr, unrelated,
                orient);
    EXPECT_GT(corr, 0.5);
    EXPECT_GT(corr, unrelated + 0.2);
    EXPECT_GT(orient, 0.7);
  }
}

TEST(PhotoTrueVolume, ASliceAlongTheFibresShowsTheGrain) {
  const VolumeFixture& f = fixture();
  const PhotoTrueVolume& v = f.volume;
  for (int axis : {0, 1, 2}) {
    if (axis == v.sliceAxis) continue;
    const Image slice = volumeSlice(v, axis, kSide / 2), truth = modelSlice(*f.model, v, axis, kSide / 2);
    const double corr = bandPassCorrelation(slice, truth),
                 unrelated = bandPassCorrelation(rotatedQuarter(truth), truth);
    const double orient = orientationAgreement(slice, truth);
    std::printf(
        "slice along the fibres (axis %d): corr %.3f (unrelated %.3f), orient %.3f (unrelated %.3f)\n", axis,
        corr, unrelated, orient, orientationAgreement(rotatedQuarter(truth), truth));
    EXPECT_GT(orient, 0.6);
    EXPECT_GT(corr, unrelated + 0.2);
  }
}

TEST(PhotoTrueVolume, ConsecutiveSlicesContinueEachOther) {
  const VolumeFixture& f = fixture();
  const PhotoTrueVolume& v = f.volume;
  // Two neighbouring slices of the volume against the same two planes synthesised each on its own (as two
  // cuts would be): the volume's pores and rays go on from one to the next, the separate cuts' do not.
  const int k = kSide / 2;
  const Image a = volumeSlice(v, v.sliceAxis, k), b = volumeSlice(v, v.sliceAxis, k + 1);
  const int axis = v.sliceAxis;
  const float z0 = v.origin[axis] + k * v.spacing[axis], z1 = z0 + v.spacing[axis];
  const float pxPerMm = 1.0f / v.spacing[axis == 0 ? 1 : 0];
  auto cut = [&](float z) {
    glm::vec3 point(0.0f), normal(0.0f);
    point[axis] = z, normal[axis] = 1;
    const Image rgba = f.appearance->renderCut(CutPlane(point, normal), pxPerMm);
    Image rgb(rgba.width, rgba.height, 3);
    for (int y = 0; y < rgb.height; ++y)
      for (int x = 0; x < rgb.width; ++x) std::copy_n(rgba.pixel(x, y), 3, rgb.pixel(x, y));
    return rgb;
  };
  const Image ca = cut(z0), cb = cut(z1);
  ASSERT_EQ(ca.width, a.width);
  // The detail finer than the rings (luminance minus its blur over 1.5 px): the rings agree in both
  // pairs (the field places them), the pores and rays only where the volume carries them on.
  auto detail = [](const Image& image) {
    const cv::Mat l = luminance(image);
    cv::Mat blurred;
    cv::GaussianBlur(l, blurred, cv::Size(0, 0), 1.5);
    return cv::Mat(l - blurred);
  };
  auto correlation = [](const cv::Mat& x0, const cv::Mat& y0) {
    const cv::Mat x = x0 - cv::mean(x0)[0], y = y0 - cv::mean(y0)[0];
    return x.dot(y) / std::sqrt(x.dot(x) * y.dot(y) + 1e-12);
  };
  const double together = correlation(detail(a), detail(b)), apart = correlation(detail(ca), detail(cb));
  std::printf("neighbouring slices, fine detail: volume %.3f, separate cuts %.3f; band-pass %.3f, %.3f\n",
              together, apart, bandPassCorrelation(a, b), bandPassCorrelation(ca, cb));
  // Measured 0.946 against 0.814 (at the demo's 1.6 px/mm the finest detail is mostly ring edges, which
  // the separate cuts share through the field).
  EXPECT_GT(together, 0.9);
  EXPECT_GT(together, apart + 0.08);
}

TEST(PhotoTrueVolume, ExportWritesTheVolumesColoursAndSaysWhoseTheyAre) {
  const fs::path dir = scratchFolder("photo-true-volume", "export");
  Project project = demoProject(7);
  const WoodModel model(project);
  for (FaceId face : kAllFaces) {
    const fs::path file = dir / (std::string(1, faceLetter(face)) + "_col.png");
    writeImage(file, renderFace(model, face, {kSide, kSide}, 2));
    project.facePhotos[faceIndex(face)] = file;
  }
  project.appearance = Appearance::Photo;
  ExportRequest request;
  request.out = dir / "colour.nrrd";
  request.quantity = VolumeQuantity::Color;
  request.resolution = 32;  // coarser than the photos: the volume is sampled at the export's voxels
  request.photoTrue = photoTrueSourceOf(project);
  const ExportSummary summary = runExport(model, request);
  EXPECT_NE(summary.message.find("in the photo-true appearance (32 x 32 x 32 samples"), std::string::npos)
      << summary.message;
  EXPECT_TRUE(summary.warning.empty()) << summary.warning;
  const NrrdHeader header = readNrrdHeader(request.out);
  EXPECT_EQ(header.keyValue("appearance"), "photo-true");
  std::ifstream in(request.out, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  ASSERT_EQ(bytes.size(), header.dataOffset + 32 * 32 * 32 * 3);
  // The same appearance as every command makes it, sampled at the voxel centres.
  const PhotoTrueAppearance appearance(model, loadAppearancePhotos(project), {}, photoTrueOptionsFor(model));
  const PhotoTrueVolume volume = appearance.renderVolume({32, 32, 32});
  EXPECT_EQ(volume.size[volume.sliceAxis], 32);  // along the slices no more than the export asks
  const float spacing = 40.0f / 32;
  int differing = 0;
  for (int z = 0; z < 32; ++z)
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        const glm::vec3 p = glm::vec3(-20.0f + (x + 0.5f) * spacing, -20.0f + (y + 0.5f) * spacing,
                                      -20.0f + (z + 0.5f) * spacing);
        const glm::vec3 c = volume.colourAt(p);
        const std::size_t i = header.dataOffset + ((std::size_t(z) * 32 + y) * 32 + x) * 3;
        for (int ch = 0; ch < 3; ++ch)
          differing += static_cast<unsigned char>(bytes[i + ch]) != std::lround(c[ch] * 255.0f) ? 1 : 0;
      }
  EXPECT_EQ(differing, 0);
  // Not the procedural model's colours: the same export of a procedural project differs in most voxels.
  ExportRequest proceduralRequest = request;
  proceduralRequest.out = dir / "procedural.nrrd";
  proceduralRequest.photoTrue.reset();
  runExport(model, proceduralRequest);
  EXPECT_EQ(readNrrdHeader(proceduralRequest.out).keyValue("appearance"), "procedural");
  std::ifstream proceduralIn(proceduralRequest.out, std::ios::binary);
  const std::string proceduralBytes((std::istreambuf_iterator<char>(proceduralIn)), {});
  ASSERT_EQ(proceduralBytes.size(), bytes.size());
  int unlike = 0;
  for (std::size_t i = header.dataOffset; i < bytes.size(); ++i)
    unlike += std::abs(int(static_cast<unsigned char>(bytes[i])) -
                       int(static_cast<unsigned char>(proceduralBytes[i]))) > 2
                  ? 1
                  : 0;
  EXPECT_GT(unlike, int(bytes.size() - header.dataOffset) / 4);
  // Cancelled: nothing written.
  std::stop_source stop;
  stop.request_stop();
  request.out = dir / "cancelled.nrrd";
  EXPECT_THROW(runExport(model, request, {nullptr, stop.get_token()}), Cancelled);
  EXPECT_FALSE(fs::exists(request.out));
}

TEST(PhotoTrueVolume, DeterministicForASeedWhateverTheThreads) {
  const VolumeFixture& f = fixture();
  const int threads = workerThreads();
  setWorkerThreads(1);
  glm::ivec3 samples(kSide);
  samples[f.volume.sliceAxis] = 16;  // 16 slices
  const PhotoTrueVolume one = f.appearance->renderVolume(samples);
  setWorkerThreads(2);
  const PhotoTrueVolume two = f.appearance->renderVolume(samples);
  setWorkerThreads(threads);
  EXPECT_EQ(one.size, samples);
  EXPECT_EQ(one.rgb, two.rgb);
}
