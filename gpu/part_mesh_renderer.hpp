#pragma once
// A placed part (core/mesh/) in the 3D view: its triangles in block mm with their normals, in vertex
// buffers laid out as shaders/block.vert reads them (location 0 position, 1 normal; 2, the photo uv,
// is left at its default), so the block's wood program colours it per fragment from the same GLSL wood
// model (Viewport3D draws it with block.frag's part pass). Needs a current OpenGL context for every call.
#include <QOpenGLExtraFunctions>

#include "mesh/mesh.hpp"

namespace kerf {

class PartMeshRenderer {
 public:
  PartMeshRenderer();
  ~PartMeshRenderer();  // the GL objects must be freed with release() first, with the context current
  PartMeshRenderer(const PartMeshRenderer&) = delete;
  PartMeshRenderer& operator=(const PartMeshRenderer&) = delete;

  void upload(const Mesh& placedMesh);  // normals computed per face where the mesh has none
  void draw();                          // the bound program's attributes 0 and 1
  void release();
  bool empty() const { return indexCount_ == 0; }

 private:
  QOpenGLExtraFunctions* gl_ = nullptr;
  unsigned vertexArray_ = 0, vertexBuffer_ = 0, indexBuffer_ = 0;
  int indexCount_ = 0;
};

}  // namespace kerf
