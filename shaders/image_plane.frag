// The wood on a plane, one fragment per image pixel: faces (renderFace) and cuts (renderCut) of
// core/render/renderers.cpp, on the GPU. Pixel (c, r) of an image of `u_imageHeight` rows lies at
// u_planeOrigin + (c + 0.5) * u_pixelRight + (r + 0.5) * u_pixelDown (block mm).
uniform vec3 u_planeOrigin;  // block point at the image's top-left corner
uniform vec3 u_pixelRight;   // block mm per pixel along +column
uniform vec3 u_pixelDown;    // block mm per pixel along +row
uniform float u_imageHeight;
uniform int u_faceIndex;     // 0..5 = that face's tint, -1 = none
uniform vec3 u_blockHalfSize;
uniform bool u_clipToBlock;  // cuts: transparent outside the block

out vec4 fragColor;

void main() {
  vec2 pos = vec2(gl_FragCoord.x, u_imageHeight - gl_FragCoord.y);  // image rows grow downward
  vec3 p = u_planeOrigin + pos.x * u_pixelRight + pos.y * u_pixelDown;
  if (u_clipToBlock && any(greaterThan(abs(p), u_blockHalfSize + 1e-4))) {
    fragColor = vec4(0.0);
    return;
  }
#ifdef KERF_BOARD_WOOD
  fragColor = vec4(boardWood(p).color, 1.0);  // a board cut from a log (board_wood.glsl)
#else
  fragColor = vec4(evaluateWood(p, u_faceIndex, false).color, 1.0);
#endif
}
