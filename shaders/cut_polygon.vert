// The cut polygon (CutView), in normalized device coordinates: only fragments on the wood are
// generated, and image_plane.frag works out the block point of each one, as for a full-screen triangle.
layout(location = 0) in vec2 a_position;
void main() { gl_Position = vec4(a_position, 0.0, 1.0); }
