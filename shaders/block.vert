// The block's faces and the cut surface in the 3D view (widgets/viewport3d.cpp). Positions are block
// millimetres; block.frag evaluates the wood model at every fragment's block position.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_photoUv;  // Block::blockToImage of the vertex, divided by the image size

uniform mat4 u_viewProjection;

out vec3 v_position;
out vec3 v_normal;
out vec2 v_photoUv;

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_photoUv = a_photoUv;
  gl_Position = u_viewProjection * vec4(a_position, 1.0);
}
