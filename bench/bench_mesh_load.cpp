// Loading a part mesh whose one vertex is on many triangles (issue 21): a closed cone of 2 x sides
// triangles, apex and base centre each on `sides` of them. Linear in the triangles since the loader makes
// its own normals and joins vertices by hashing (mesh/mesh_normals.hpp); assimp's GenSmoothNormals and
// JoinIdenticalVertices took 41 s for 40000 sides. docs/reliability.md has the figures.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "mesh/mesh_loader.hpp"
#include "part_meshes.hpp"

namespace {

void BM_LoadClosedCone(benchmark::State& state) {
  const int sides = static_cast<int>(state.range(0));
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("kerf_bench_cone_" + std::to_string(sides) + ".obj");
  kerf::testing::writeConeObj(path, 10.0f, 30.0f, sides);
  for (auto _ : state) benchmark::DoNotOptimize(kerf::loadMesh(path));
  state.counters["triangles"] = 2.0 * sides;
  state.SetItemsProcessed(state.iterations() * 2 * sides);
  std::filesystem::remove(path);
}
BENCHMARK(BM_LoadClosedCone)->Arg(2500)->Arg(10000)->Arg(40000)->Unit(benchmark::kMillisecond);

}  // namespace
