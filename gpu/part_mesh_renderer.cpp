#include "gpu/part_mesh_renderer.hpp"

#include <QOpenGLContext>
#include <cstddef>
#include <glm/geometric.hpp>
#include <vector>

namespace kerf {
namespace {

struct PartVertex {
  glm::vec3 position, normal;
};

}  // namespace

PartMeshRenderer::PartMeshRenderer() = default;
PartMeshRenderer::~PartMeshRenderer() = default;

void PartMeshRenderer::upload(const Mesh& mesh) {
  if (!gl_) {
    gl_ = QOpenGLContext::currentContext()->extraFunctions();
    gl_->glGenVertexArrays(1, &vertexArray_);
    gl_->glGenBuffers(1, &vertexBuffer_);
    gl_->glGenBuffers(1, &indexBuffer_);
    gl_->glBindVertexArray(vertexArray_);
    gl_->glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    gl_->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);  // recorded in the vertex array
    gl_->glEnableVertexAttribArray(0);
    gl_->glEnableVertexAttribArray(1);
    gl_->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(PartVertex),
                               reinterpret_cast<void*>(offsetof(PartVertex, position)));
    gl_->glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(PartVertex),
                               reinterpret_cast<void*>(offsetof(PartVertex, normal)));
    gl_->glBindVertexArray(0);
  }
  std::vector<PartVertex> vertices;
  std::vector<unsigned> indices;
  if (mesh.hasNormals()) {
    vertices.reserve(mesh.positions.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      vertices.push_back({mesh.positions[i], mesh.normals[i]});
    for (const glm::uvec3& t : mesh.triangles) indices.insert(indices.end(), {t.x, t.y, t.z});
  } else {  // flat shading: each triangle its own corners
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
      const glm::vec3 n = glm::cross(b - a, c - a);
      const glm::vec3 unit = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0, 0, 1);
      for (const glm::vec3& p : {a, b, c}) {
        indices.push_back(static_cast<unsigned>(vertices.size()));
        vertices.push_back({p, unit});
      }
    }
  }
  gl_->glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
  gl_->glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(PartVertex)),
                    vertices.data(), GL_STATIC_DRAW);
  gl_->glBindBuffer(GL_ARRAY_BUFFER, 0);
  gl_->glBindVertexArray(vertexArray_);
  gl_->glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(unsigned)),
                    indices.data(), GL_STATIC_DRAW);
  gl_->glBindVertexArray(0);
  indexCount_ = static_cast<int>(indices.size());
}

void PartMeshRenderer::draw() {
  if (empty()) return;
  gl_->glBindVertexArray(vertexArray_);
  gl_->glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  gl_->glBindVertexArray(0);
}

void PartMeshRenderer::release() {
  if (!gl_) return;
  gl_->glDeleteVertexArrays(1, &vertexArray_);
  gl_->glDeleteBuffers(1, &vertexBuffer_);
  gl_->glDeleteBuffers(1, &indexBuffer_);
  gl_ = nullptr;
  indexCount_ = 0;
}

}  // namespace kerf
