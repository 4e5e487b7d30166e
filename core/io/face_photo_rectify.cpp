#include "io/face_photo_rectify.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "util/error.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

float cross(glm::vec2 a, glm::vec2 b) {
  return a.x * b.y - a.y * b.x;
}

std::string point(glm::vec2 p) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.1f, %.1f)", p.x, p.y);
  return text;
}

float luminance(const float* rgb) {
  return 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
}

glm::vec3 gainsFor(glm::vec3 reference) {
  const float y = 0.2126f * reference.x + 0.7152f * reference.y + 0.0722f * reference.z;
  glm::vec3 gains;
  for (int c = 0; c < 3; ++c) gains[c] = std::clamp(y / std::max(reference[c], 1e-6f), 0.25f, 4.0f);
  return gains;
}

// A cv::Mat header over the image's pixels (no copy); the caller keeps `image` alive.
cv::Mat matOf(const Image& image) {
  return cv::Mat(image.height, image.width, CV_32FC(image.channels), const_cast<float*>(image.pixels.data()));
}

Image imageOf(const cv::Mat& mat) {
  Image image(mat.cols, mat.rows, mat.channels());
  cv::Mat view = matOf(image);
  mat.copyTo(view);
  return image;
}

}  // namespace

int normalizedRotation(int degrees) {
  if (degrees % 90 != 0)
    throw InputError("rotation must be a quarter turn (0, 90, 180 or 270 degrees), not " +
                     std::to_string(degrees));
  return ((degrees % 360) + 360) % 360;
}

void validateCorners(const std::array<glm::vec2, 4>& corners, glm::ivec2 photoSize) {
  for (int k = 0; k < 4; ++k) {
    const glm::vec2 p = corners[k];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      throw InputError("corner " + std::to_string(k + 1) + " is not a number");
    if (p.x < -1.0f || p.y < -1.0f || p.x > photoSize.x + 1.0f || p.y > photoSize.y + 1.0f)
      throw InputError("corner " + std::to_string(k + 1) + " " + point(p) + " lies outside the photo (" +
                       std::to_string(photoSize.x) + " x " + std::to_string(photoSize.y) + " px)");
  }
  for (int k = 0; k < 4; ++k) {
    const float side = glm::length(corners[(k + 1) % 4] - corners[k]);
    if (side < 4.0f)
      throw InputError("corners " + std::to_string(k + 1) + " and " + std::to_string((k + 1) % 4 + 1) +
                       " are only " + std::to_string(side).substr(0, 4) +
                       " px apart: pick the four corners of the face, not one point");
  }
  // The turn at each corner: positive = clockwise on the photo (y grows downwards).
  std::array<float, 4> turn{};
  int clockwise = 0, anticlockwise = 0;
  for (int k = 0; k < 4; ++k) {
    const glm::vec2 in = corners[k] - corners[(k + 3) % 4], out = corners[(k + 1) % 4] - corners[k];
    turn[k] = cross(in, out) / (glm::length(in) * glm::length(out));  // sine of the turn
    if (std::abs(turn[k]) < 0.035f)                                   // 2 degrees
      throw InputError("corners " + std::to_string((k + 3) % 4 + 1) + ", " + std::to_string(k + 1) + " and " +
                       std::to_string((k + 1) % 4 + 1) +
                       " lie on one line: the four corners must make a four-sided face");
    (turn[k] > 0 ? clockwise : anticlockwise) += 1;
  }
  const std::string order =
      "(top-left, top-right, bottom-right, bottom-left as the face appears on the photo)";
  if (anticlockwise == 4)
    throw InputError("the corners go anticlockwise round the face: give them clockwise " + order +
                     "; to mirror the face, use flip");
  if (clockwise != 4) {
    int odd = 0;
    for (int k = 0; k < 4; ++k)
      if ((turn[k] > 0) != (clockwise > anticlockwise)) odd = k;
    throw InputError(
        "the corners do not make a convex four-sided face (the outline crosses itself or dents in at "
        "corner " +
        std::to_string(odd + 1) + "): give them in order round the face " + order);
  }
  float area = 0;
  for (int k = 0; k < 4; ++k) area += cross(corners[k], corners[(k + 1) % 4]);
  if (0.5f * area < 64.0f)
    throw InputError("the face outlined by the corners covers only " +
                     std::to_string(0.5f * area).substr(0, 4) +
                     " px^2 of the photo; pick the corners of the whole face");
}

glm::vec2 orientPoint(glm::vec2 p, glm::ivec2 size, int rotationDegrees, bool flip) {
  const float w = static_cast<float>(size.x), h = static_cast<float>(size.y);
  glm::vec2 q;
  float width;  // of the turned picture
  switch (normalizedRotation(rotationDegrees)) {
    case 90:
      q = {h - p.y, p.x};
      width = h;
      break;
    case 180:
      q = {w - p.x, h - p.y};
      width = w;
      break;
    case 270:
      q = {p.y, w - p.x};
      width = h;
      break;
    default:
      q = p;
      width = w;
  }
  if (flip) q.x = width - q.x;
  return q;
}

int orientedSide(int side, int rotationDegrees, bool flip) {
  int s = (side + normalizedRotation(rotationDegrees) / 90) % 4;
  if (flip && (s % 2 == 1)) s = 4 - s;  // right <-> left
  return s;
}

std::array<FaceId, 4> faceEdgeNeighbours(FaceId face) {
  const Block block;
  const FaceFrame f = block.face(face);
  const glm::vec3 outward[4] = {-f.down, f.right, f.down, -f.right};
  std::array<FaceId, 4> result{};
  for (int side = 0; side < 4; ++side)
    for (FaceId other : kAllFaces)
      if (glm::dot(block.face(other).normal, outward[side]) > 0.9f) result[side] = other;
  return result;
}

Image orientImage(const Image& image, int rotationDegrees, bool flip) {
  const int rotation = normalizedRotation(rotationDegrees);
  const bool quarter = rotation == 90 || rotation == 270;
  Image out(quarter ? image.height : image.width, quarter ? image.width : image.height, image.channels);
  const glm::ivec2 size(image.width, image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec2 q = orientPoint(glm::vec2(x + 0.5f, y + 0.5f), size, rotation, flip);
      std::copy_n(image.pixel(x, y), image.channels,
                  out.pixel(static_cast<int>(std::floor(q.x)), static_cast<int>(std::floor(q.y))));
    }
  return out;
}

glm::vec2 photoResolution(const std::array<glm::vec2, 4>& corners, glm::vec2 faceMm, int rotationDegrees) {
  const int rotation = normalizedRotation(rotationDegrees);
  const glm::vec2 mm = (rotation == 90 || rotation == 270) ? glm::vec2(faceMm.y, faceMm.x) : faceMm;
  glm::vec2 range(1e30f, 0.0f);
  for (int k = 0; k < 4; ++k) {
    const float r = glm::length(corners[(k + 1) % 4] - corners[k]) / (k % 2 == 0 ? mm.x : mm.y);
    range = {std::min(range.x, r), std::max(range.y, r)};
  }
  return range;
}

Image rectifyFace(const Image& photo, const FacePhotoSetup& setup, glm::ivec2 faceSize) {
  if (photo.empty()) throw InputError("the photo is empty");
  checkImageSize(faceSize, "the face image");
  if (photo.channels < 1 || photo.channels > 4)
    throw InputError("photos with " + std::to_string(photo.channels) + " channels are not supported");
  const int rotation = normalizedRotation(setup.rotationDegrees);
  validateCorners(setup.corners, {photo.width, photo.height});
  const bool quarter = rotation == 90 || rotation == 270;
  const int w = quarter ? faceSize.y : faceSize.x, h = quarter ? faceSize.x : faceSize.y;

  // Only the face's neighbourhood of the photo is used.
  float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
  for (glm::vec2 p : setup.corners) {
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  }
  const int margin = 4;
  const int rx0 = std::clamp(static_cast<int>(std::floor(x0)) - margin, 0, photo.width - 1);
  const int ry0 = std::clamp(static_cast<int>(std::floor(y0)) - margin, 0, photo.height - 1);
  const int rx1 = std::clamp(static_cast<int>(std::ceil(x1)) + margin, rx0 + 1, photo.width);
  const int ry1 = std::clamp(static_cast<int>(std::ceil(y1)) + margin, ry0 + 1, photo.height);
  const cv::Mat full = matOf(photo);
  cv::Mat source = full(cv::Rect(rx0, ry0, rx1 - rx0, ry1 - ry0));

  // Photo pixels per output pixel along the least-shrunk side; average down what is far above 1.5.
  float shrink = 1e30f;
  for (int k = 0; k < 4; ++k)
    shrink = std::min(shrink, glm::length(setup.corners[(k + 1) % 4] - setup.corners[k]) /
                                  static_cast<float>(k % 2 == 0 ? w : h));
  glm::vec2 scale(1.0f);
  if (shrink > 2.0f) {
    const float f = 1.5f / shrink;
    const cv::Size size(std::max(1, static_cast<int>(std::lround(source.cols * f))),
                        std::max(1, static_cast<int>(std::lround(source.rows * f))));
    cv::Mat reduced;
    cv::resize(source, reduced, size, 0, 0, cv::INTER_AREA);
    scale = {static_cast<float>(size.width) / source.cols, static_cast<float>(size.height) / source.rows};
    source = reduced;
  }

  // OpenCV puts pixel centres at integer coordinates, Kerf at +0.5: shift both ends by half a pixel.
  cv::Point2f from[4], to[4];
  const glm::vec2 origin(static_cast<float>(rx0), static_cast<float>(ry0));
  const glm::vec2 target[4] = {{0, 0}, {w, 0}, {w, h}, {0, h}};
  for (int k = 0; k < 4; ++k) {
    const glm::vec2 p = (setup.corners[k] - origin) * scale - 0.5f;
    from[k] = {p.x, p.y};
    to[k] = {target[k].x - 0.5f, target[k].y - 0.5f};
  }
  const cv::Mat homography = cv::getPerspectiveTransform(from, to);
  cv::Mat warped;
  cv::warpPerspective(source, warped, homography, cv::Size(w, h), cv::INTER_CUBIC, cv::BORDER_REPLICATE);
  cv::min(cv::max(warped, 0.0), 1.0, warped);  // bicubic overshoot at sharp ring edges

  Image face = orientImage(imageOf(warped), rotation, setup.flip);
  applyWhiteBalance(face, setup.whiteBalance);
  return face;
}

Image rectifyFacePhoto(const FacePhotoSetup& setup, glm::ivec2 faceSize) {
  const Image photo = readImage(setup.source);
  try {
    return rectifyFace(photo, setup, faceSize);
  } catch (const InputError& e) {
    throw InputError(setup.source.string() + ": " + e.what());
  }
}

glm::vec3 whiteBalanceFromPatch(const Image& photo, glm::vec4 rect) {
  if (photo.channels < 3) return glm::vec3(1.0f);
  if (!(rect.z > 0 && rect.w > 0) || !std::isfinite(rect.x) || !std::isfinite(rect.y))
    throw InputError("the neutral patch has no area");
  const int cx0 = std::max(0, static_cast<int>(std::ceil(rect.x - 0.5f)));
  const int cy0 = std::max(0, static_cast<int>(std::ceil(rect.y - 0.5f)));
  const int cx1 = std::min(photo.width - 1, static_cast<int>(std::floor(rect.x + rect.z - 0.5f)));
  const int cy1 = std::min(photo.height - 1, static_cast<int>(std::floor(rect.y + rect.w - 0.5f)));
  if (cx1 < cx0 || cy1 < cy0)
    throw InputError("the neutral patch " + point({rect.x, rect.y}) +
                     " is outside the photo or smaller than a pixel");
  glm::dvec3 sum(0.0);
  std::size_t count = 0, clipped = 0;
  for (int y = cy0; y <= cy1; ++y)
    for (int x = cx0; x <= cx1; ++x) {
      const float* p = photo.pixel(x, y);
      sum += glm::dvec3(p[0], p[1], p[2]);
      if (std::max({p[0], p[1], p[2]}) >= 0.99f) ++clipped;
      ++count;
    }
  const glm::vec3 mean = glm::vec3(sum / static_cast<double>(count));
  if (std::min({mean.x, mean.y, mean.z}) < 0.02f)
    throw InputError(
        "the neutral patch is too dark to tell the light's colour; pick a light grey or white area");
  if (clipped * 2 > count)
    throw InputError(
        "the neutral patch is over-exposed (most of it is pure white); pick a grey area or "
        "expose the photo less");
  return gainsFor(mean);
}

glm::vec3 autoWhiteBalance(const Image& photo) {
  if (photo.channels < 3 || photo.empty()) return glm::vec3(1.0f);
  const double pixels = static_cast<double>(photo.width) * photo.height;
  const int step = std::max(1, static_cast<int>(std::ceil(std::sqrt(pixels / 250000.0))));
  std::vector<float> luma;
  luma.reserve(static_cast<std::size_t>(pixels / (step * step)) + 1);
  for (int y = step / 2; y < photo.height; y += step)
    for (int x = step / 2; x < photo.width; x += step) {
      const float* p = photo.pixel(x, y);
      if (std::max({p[0], p[1], p[2]}) < 0.98f) luma.push_back(luminance(p));
    }
  if (luma.size() < 16) return glm::vec3(1.0f);
  std::vector<float> sorted = luma;
  const auto at = [&](double q) {
    auto nth = sorted.begin() + static_cast<std::ptrdiff_t>(q * (sorted.size() - 1));
    std::nth_element(sorted.begin(), nth, sorted.end());
    return *nth;
  };
  const float low = at(0.97), high = at(0.995);
  glm::dvec3 sum(0.0);
  std::size_t count = 0;
  for (int y = step / 2; y < photo.height; y += step)
    for (int x = step / 2; x < photo.width; x += step) {
      const float* p = photo.pixel(x, y);
      if (std::max({p[0], p[1], p[2]}) >= 0.98f) continue;
      const float l = luminance(p);
      if (l >= low && l <= high) sum += glm::dvec3(p[0], p[1], p[2]), ++count;
    }
  if (count == 0) return glm::vec3(1.0f);
  const glm::vec3 reference = glm::vec3(sum / static_cast<double>(count));
  if (luminance(&reference.x) < 0.05f) return glm::vec3(1.0f);
  return gainsFor(reference);
}

void applyWhiteBalance(Image& image, glm::vec3 gains) {
  if (image.channels < 3 || gains == glm::vec3(1.0f)) return;
  const std::size_t count = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t i = 0; i < count; ++i) {
    float* p = &image.pixels[i * image.channels];
    for (int c = 0; c < 3; ++c) p[c] = std::clamp(p[c] * gains[c], 0.0f, 1.0f);
  }
}

Image downscaleImage(const Image& photo, int maxSide) {
  const int longest = std::max(photo.width, photo.height);
  if (photo.empty() || maxSide < 1 || longest <= maxSide) return photo;
  const double f = static_cast<double>(maxSide) / longest;
  const cv::Size size(std::max(1, static_cast<int>(std::lround(photo.width * f))),
                      std::max(1, static_cast<int>(std::lround(photo.height * f))));
  cv::Mat reduced;
  cv::resize(matOf(photo), reduced, size, 0, 0, cv::INTER_AREA);
  return imageOf(reduced);
}

std::optional<FaceId> faceFromFileName(const std::string& fileName) {
  if (fileName.size() < 2) return std::nullopt;
  const char separator = fileName[1];
  if (separator != '_' && separator != '-' && separator != '.' && separator != ' ') return std::nullopt;
  return faceFromLetter(fileName[0]);
}

}  // namespace kerf
