#include "render/batch_evaluator.hpp"

#include <algorithm>
#include <stdexcept>

#include "util/parallel.hpp"

namespace kerf {
namespace {

constexpr std::size_t kChunk = 4096;

template <class Body>
void forChunks(std::size_t count, const Progress& progress, Body body) {
  const int chunks = static_cast<int>((count + kChunk - 1) / kChunk);
  parallelRows(
      chunks,
      [&](int chunk) {
        const std::size_t begin = static_cast<std::size_t>(chunk) * kChunk;
        const std::size_t end = std::min(count, begin + kChunk);
        for (std::size_t i = begin; i < end; ++i) body(i);
      },
      progress);
}

}  // namespace

void evaluateYears(const WoodModel& model, std::span<const glm::vec3> points, std::span<float> years,
                   const Progress& progress) {
  if (points.size() != years.size()) throw std::invalid_argument("evaluateYears: spans differ in size");
  forChunks(points.size(), progress, [&](std::size_t i) { years[i] = model.material().year(points[i]); });
}

void evaluateColors(const WoodModel& model, std::span<const glm::vec3> points, std::span<glm::vec3> colors,
                    const Progress& progress) {
  if (points.size() != colors.size()) throw std::invalid_argument("evaluateColors: spans differ in size");
  forChunks(points.size(), progress, [&](std::size_t i) { colors[i] = model.evaluate(points[i]).color; });
}

}  // namespace kerf
