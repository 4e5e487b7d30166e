// The wood of a board cut from a log at a board point (render/board_wood.hpp), for the 3D view and the
// cut panel in log mode: block.frag and image_plane.frag call boardWood() instead of evaluateWood() when
// KERF_BOARD_WOOD is defined (WoodProgram, WoodSource::Board). Appended to knots.glsl.
//
// The knots evaluated are those listed for the point's cell of a coarse grid over the board
// (KnotCellGrid): every other knot contributes exactly nothing there, so this equals the evaluation over
// all knots (KnotField::evaluate), as core's boardWoodColor does.
uniform vec3 u_boardCenter;  // log frame, mm
uniform mat3 u_boardAxes;    // columns: the board's x, y, z axes in the log frame (Board::axes)
uniform vec3 u_boardSize;    // mm
uniform ivec3 u_cellCount;
uniform isampler3D u_cells;  // RG32I: (first, count) into u_tileKnots, per cell

WoodSample boardWood(vec3 p) {
  vec3 logPoint = u_boardCenter + u_boardAxes * p;
  ivec3 cell = clamp(ivec3(floor((p / u_boardSize + 0.5) * vec3(u_cellCount))), ivec3(0), u_cellCount - 1);
  ivec2 range = texelFetch(u_cells, cell, 0).rg;
  KnotSample k = evaluateKnots(logPoint, range.x, range.y);
  WoodSample s;
  s.year = k.time;
  s.latewood = 1.0;  // the colour map has the rings; the finish's gloss stays even
  s.pigment = 1.0;
  s.pore = 0.0;
  s.shade = vec3(1.0);
  s.ray = 0.0;
  s.color = knotColor(k);
  // The fibres run up the log: its axis in the board frame (the transposed rotation's z column).
  s.fiberDirection = vec3(u_boardAxes[0].z, u_boardAxes[1].z, u_boardAxes[2].z);
  return s;
}
