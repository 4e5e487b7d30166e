#pragma once
// Tiny meshes the part tests write themselves (no binary fixtures): a box as OBJ with quads, a
// prism (an n-sided cylinder along y, capped) as ASCII STL and as ASCII PLY.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace kerf::testing {

// Boxes from min to max corner, each with its own 8 vertices and 6 quads (counter-clockwise seen from
// outside), no normals or uvs. skipFaces: how many of the last box's quads to leave out (an open box).
inline std::filesystem::path writeBoxesObj(const std::filesystem::path& path,
                                           const std::vector<std::pair<glm::vec3, glm::vec3>>& boxes,
                                           int skipFaces = 0) {
  std::ofstream f(path);
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    const auto [lo, hi] = boxes[b];
    for (int i = 0; i < 8; ++i)
      f << "v " << ((i & 1) ? hi.x : lo.x) << ' ' << ((i & 2) ? hi.y : lo.y) << ' ' << ((i & 4) ? hi.z : lo.z)
        << '\n';
    const int faces[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5},
                             {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
    const int count = b + 1 == boxes.size() ? 6 - skipFaces : 6;
    for (int q = 0; q < count; ++q) {
      f << 'f';
      for (int k : faces[q]) f << ' ' << k + 8 * b;
      f << '\n';
    }
  }
  return path;
}

// A closed cone (issue 21): its apex at (0, 0, height) and the centre of its base at the origin are each
// on `sides` triangles, so one vertex has a valence that grows with the mesh. OBJ, no normals.
inline std::filesystem::path writeConeObj(const std::filesystem::path& path, float radius, float height,
                                          int sides) {
  std::ofstream f(path);
  f << "v 0 0 " << height << "\nv 0 0 0\n";
  for (int i = 0; i < sides; ++i) {
    const double a = 2.0 * M_PI * i / sides;
    f << "v " << radius * std::cos(a) << ' ' << radius * std::sin(a) << " 0\n";
  }
  for (int i = 0; i < sides; ++i) {
    const int here = i + 3, next = (i + 1) % sides + 3;  // the last side closes exactly
    f << "f 1 " << here << ' ' << next << "\nf 2 " << next << ' ' << here << '\n';
  }
  return path;
}

// A box [-h, h] around the origin (h = size / 2).
inline std::filesystem::path writeBoxObj(const std::filesystem::path& path, glm::vec3 size) {
  return writeBoxesObj(path, {{-0.5f * size, 0.5f * size}});
}

// The prism's triangles, counter-clockwise from outside: radius r, y from -h/2 to h/2, n sides.
inline std::vector<glm::vec3> prismTriangles(float radius, float height, int sides) {
  std::vector<glm::vec3> t;
  const float y0 = -height / 2, y1 = height / 2;
  for (int i = 0; i < sides; ++i) {
    const float a0 = 2.0f * float(M_PI) * i / sides,
                a1 = 2.0f * float(M_PI) * ((i + 1) % sides) / sides;  // the last side closes exactly
    const glm::vec3 p0(radius * std::cos(a0), 0, -radius * std::sin(a0));
    const glm::vec3 p1(radius * std::cos(a1), 0, -radius * std::sin(a1));
    const glm::vec3 b0 = p0 + glm::vec3(0, y0, 0), b1 = p1 + glm::vec3(0, y0, 0);
    const glm::vec3 t0 = p0 + glm::vec3(0, y1, 0), t1 = p1 + glm::vec3(0, y1, 0);
    t.insert(t.end(), {b0, b1, t1, b0, t1, t0});       // side
    t.insert(t.end(), {glm::vec3(0, y1, 0), t0, t1});  // top cap
    t.insert(t.end(), {glm::vec3(0, y0, 0), b1, b0});  // bottom cap
  }
  return t;
}

inline std::filesystem::path writePrismStl(const std::filesystem::path& path, float radius, float height,
                                           int sides) {
  const std::vector<glm::vec3> t = prismTriangles(radius, height, sides);
  std::ofstream f(path);
  f << "solid prism\n";
  for (std::size_t i = 0; i < t.size(); i += 3) {
    const glm::vec3 n = glm::normalize(glm::cross(t[i + 1] - t[i], t[i + 2] - t[i]));
    f << " facet normal " << n.x << ' ' << n.y << ' ' << n.z << "\n  outer loop\n";
    for (int k = 0; k < 3; ++k)
      f << "   vertex " << t[i + k].x << ' ' << t[i + k].y << ' ' << t[i + k].z << '\n';
    f << "  endloop\n endfacet\n";
  }
  f << "endsolid prism\n";
  return path;
}

inline std::filesystem::path writePrismPly(const std::filesystem::path& path, float radius, float height,
                                           int sides) {
  const std::vector<glm::vec3> t = prismTriangles(radius, height, sides);
  std::ofstream f(path);
  f << "ply\nformat ascii 1.0\nelement vertex " << t.size()
    << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << t.size() / 3
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const glm::vec3& p : t) f << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (std::size_t i = 0; i < t.size(); i += 3) f << "3 " << i << ' ' << i + 1 << ' ' << i + 2 << '\n';
  return path;
}

}  // namespace kerf::testing
