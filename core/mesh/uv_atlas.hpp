#pragma once
// A texture atlas for a placed part (issue 7): every triangle gets its own place in the unit square, so
// a texture baked from the wood at each texel's 3D point shows each bit of the surface exactly once.
//
// Charts: triangles are grouped by the axis their normal points along most (±x, ±y, ±z), then split into
// pieces connected by shared edges (vertices are matched by position, so files that repeat vertices per
// face, like STL, chart the same). Each chart is projected orthographically along its axis, in block mm,
// so every chart has the same texels per mm and the texture's sharpness is even over the part. A
// projection along the dominant axis never turns a triangle over, but a piece that winds round its axis
// (a helical ramp seen along it) can still cover a point twice; such a piece is found by sampling its
// projection on a grid and is split into one chart per triangle (rare for parts cut from a block; it
// costs texture space, not correctness).
//
// Packing: charts are sorted by height and laid on shelves, each with `padding` texels of gutter on
// every side; the largest texels per mm that fits is found by bisection. The bake fills the gutter
// (bake_part_texture.hpp) so mipmaps and bilinear filtering show no seams.
//
// Existing texture coordinates of the file are not used: they often tile, mirror or overlap (fine for a
// repeating texture, wrong for a bake), and their texel density varies.
#include <vector>

#include "mesh/mesh.hpp"

namespace kerf {

struct UvAtlasOptions {
  int resolution = 1024;  // the square texture's side in texels
  int padding = -1;       // gutter texels on each side of a chart; -1: max(2, resolution / 256)
  // > 0: charts no denser than this (texels per mm), even where more would fit: a bake that must work at a
  // given scale (the photo-true appearance synthesises at the photos' pixels per mm).
  float maxTexelsPerMm = 0.0f;
};

struct UvAtlas {
  // The part, split along chart borders: positions and normals of the placed mesh, uvs in [0, 1]^2
  // ((0, 0) = the texture's top-left corner, v down as in glTF).
  Mesh mesh;
  std::vector<int> sourceVertex;     // per atlas vertex: the vertex of the placed mesh it copies
  std::vector<int> chartOfTriangle;  // per triangle (same order as the placed mesh's triangles)
  struct Chart {
    int axis = 0;                             // 0..5: +x, -x, +y, -y, +z, -z
    int x = 0, y = 0, width = 0, height = 0;  // texel rectangle including the padding
  };
  std::vector<Chart> charts;
  int resolution = 0;
  int padding = 0;
  float texelsPerMm = 0.0f;
};

// Throws InputError when the charts cannot be packed at this resolution (too many separate pieces).
UvAtlas buildUvAtlas(const Mesh& placedMesh, const UvAtlasOptions& options = {});

}  // namespace kerf
