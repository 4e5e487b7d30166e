// A board face with knots, one fragment per image pixel: the GLSL twin of core's renderBoardFace
// (core/render/board_renderer.cpp). Pixel (c, r) of an image of `u_imageHeight` rows lies at
// u_origin + (c + 0.5) * u_stepX + (r + 0.5) * u_stepY (log frame, mm). The knots evaluated are those of
// the pixel's tile (u_tileSize pixels square): u_tiles holds (first, count) into the list u_tileKnots.
uniform vec3 u_origin;
uniform vec3 u_stepX;
uniform vec3 u_stepY;
uniform float u_imageHeight;
uniform int u_tileSize;
uniform isampler2D u_tiles;      // RG32I, tilesX x tilesY: first, count

out vec4 fragColor;

void main() {
  vec2 pos = vec2(gl_FragCoord.x, u_imageHeight - gl_FragCoord.y);  // image rows grow downward
  ivec2 pixel = ivec2(pos);
  ivec2 tile = texelFetch(u_tiles, pixel / u_tileSize, 0).rg;
  vec3 p = u_origin + pos.x * u_stepX + pos.y * u_stepY;
  KnotSample s = evaluateKnots(p, tile.x, tile.y);
  fragColor = vec4(knotColor(s), float(s.knotsInReach));
}
