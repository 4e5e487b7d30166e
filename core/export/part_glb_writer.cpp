#include <tiny_gltf.h>

#include <cstring>
#include <fstream>
#include <glm/glm.hpp>

#include "export/part_writers.hpp"
#include "io/atomic_file.hpp"
#include "io/png_codec.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

// Appends raw bytes to the buffer as a new buffer view (4-byte aligned, as glTF asks); returns its index.
int addBufferView(tinygltf::Model& model, const void* data, std::size_t bytes, int target) {
  std::vector<unsigned char>& buffer = model.buffers[0].data;
  buffer.resize((buffer.size() + 3) & ~std::size_t(3), 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* begin = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), begin, begin + bytes);
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size()) - 1;
}

int addAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = componentType;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

}  // namespace

void writePartGlb(const std::filesystem::path& glbPath, const Mesh& mesh, const Image& texture) {
  if (!mesh.hasUvs()) throw InputError("internal: the part has no texture coordinates to write");
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Kerf";
  model.buffers.emplace_back();

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  const std::size_t n = mesh.positions.size();
  {
    const int view =
        addBufferView(model, mesh.positions.data(), n * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    const int accessor = addAccessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
    const MeshBounds b = meshBounds(mesh.positions);  // glTF requires POSITION's bounds
    model.accessors[accessor].minValues = {b.min.x, b.min.y, b.min.z};
    model.accessors[accessor].maxValues = {b.max.x, b.max.y, b.max.z};
    primitive.attributes["POSITION"] = accessor;
  }
  if (mesh.hasNormals()) {
    const int view =
        addBufferView(model, mesh.normals.data(), n * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["NORMAL"] =
        addAccessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
  }
  {
    const int view =
        addBufferView(model, mesh.uvs.data(), n * sizeof(glm::vec2), TINYGLTF_TARGET_ARRAY_BUFFER);
    primitive.attributes["TEXCOORD_0"] =
        addAccessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n);
  }
  {
    const int view = addBufferView(model, mesh.triangles.data(), mesh.triangles.size() * sizeof(glm::uvec3),
                                   TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    primitive.indices = addAccessor(model, view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                    mesh.triangles.size() * 3);
  }

  const std::vector<unsigned char> png = encodePngBytes(texture);
  tinygltf::Image image;
  image.name = "wood";
  image.mimeType = "image/png";
  image.bufferView = addBufferView(model, png.data(), png.size(), 0);
  model.bufferViews[image.bufferView].target = 0;  // images are not vertex data
  model.images.push_back(image);

  tinygltf::Sampler sampler;
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  model.samplers.push_back(sampler);
  tinygltf::Texture gltfTexture;
  gltfTexture.sampler = 0;
  gltfTexture.source = 0;
  model.textures.push_back(gltfTexture);

  tinygltf::Material material;
  material.name = "wood";
  material.pbrMetallicRoughness.baseColorTexture.index = 0;
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.6;
  model.materials.push_back(material);
  primitive.material = 0;

  tinygltf::Mesh gltfMesh;
  gltfMesh.name = mesh.name.empty() ? "part" : mesh.name;
  gltfMesh.primitives.push_back(primitive);
  model.meshes.push_back(gltfMesh);
  tinygltf::Node node;
  node.name = "part (block frame, mm)";
  node.mesh = 0;
  node.scale = {0.001, 0.001, 0.001};  // mm -> glTF metres
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  writeFileAtomically(glbPath, [&](const std::filesystem::path& temporary) {
    std::ofstream file(temporary, std::ios::binary);
    tinygltf::TinyGLTF writer;
    if (!file || !writer.WriteGltfSceneToStream(&model, file, false, true) || !file.flush())
      throw InputError("cannot write " + glbPath.string());
  });
}

}  // namespace kerf
