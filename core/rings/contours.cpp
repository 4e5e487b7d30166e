#include "rings/contours.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace kerf {
namespace {

int scaled(int atReference, int side, int minimum) {
  return std::max(minimum, static_cast<int>(std::lround(atReference * side / 256.0)));
}

}  // namespace

std::vector<FaceContour> extractContours(const Image& arl, FaceId face, const ContourOptions& options) {
  std::vector<FaceContour> result;
  if (arl.empty() || arl.width <= 0 || arl.height <= 0) return result;
  cv::Mat mask(arl.height, arl.width, CV_8UC1);
  for (int y = 0; y < arl.height; ++y) {
    auto* row = mask.ptr<unsigned char>(y);
    for (int x = 0; x < arl.width; ++x) {
      const float v = std::clamp(arl.pixel(x, y)[0], 0.0f, 1.0f);
      const int grey = static_cast<int>(std::lround(v * 255.0f));
      row[x] = grey > options.threshold8 ? 255 : 0;
    }
  }
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  cv::findContours(mask, contours, hierarchy, cv::RETR_TREE, cv::CHAIN_APPROX_NONE);

  const int marginX = options.margin >= 0 ? options.margin : scaled(5, arl.width, 1);
  const int marginY = options.margin >= 0 ? options.margin : scaled(5, arl.height, 1);
  const int minPoints =
      options.minPoints >= 0 ? options.minPoints : scaled(32, std::max(arl.width, arl.height), 2);
  const auto isEdge = [&](const cv::Point& p) {
    return p.x <= marginX || p.x >= arl.width - marginX || p.y <= marginY || p.y >= arl.height - marginY;
  };
  const auto emit = [&](std::vector<glm::ivec2>&& pixels) {
    if (static_cast<int>(pixels.size()) > minPoints) result.push_back({face, std::move(pixels)});
  };

  for (const auto& contour : contours) {
    std::vector<glm::ivec2> head, current;
    bool seenEdge = false;
    for (const cv::Point& p : contour) {
      if (isEdge(p)) {
        if (!seenEdge) {
          seenEdge = true;
          head = std::move(current);
        } else {
          emit(std::move(current));
        }
        current.clear();
      }
      current.emplace_back(p.x, p.y);
    }
    // Never near the border: the whole contour is the last segment (same size rule).
    if (seenEdge) current.insert(current.end(), head.begin(), head.end());
    emit(std::move(current));
  }
  return result;
}

std::vector<glm::vec3> contourToBlock(const FaceContour& contour, const Block& block, glm::ivec2 imageSize,
                                      PixelAnchor anchor) {
  const float shift = anchor == PixelAnchor::KerfCentre ? 0.5f : 0.0f;
  std::vector<glm::vec3> points;
  points.reserve(contour.pixels.size());
  for (const glm::ivec2& p : contour.pixels)
    points.push_back(block.imageToBlock(contour.face, glm::vec2(p.x + shift, p.y + shift), imageSize));
  return points;
}

}  // namespace kerf
