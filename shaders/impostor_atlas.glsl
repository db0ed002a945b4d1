// An impostor atlas as the billboard pass reads it (core/scene/impostor.h;
// written by impostor_capture.frag): cells x cells squares, cell i at
// column i % cells and row i / cells, row 0 on top.
#ifndef IMPOSTOR_ATLAS_GLSL
#define IMPOSTOR_ATLAS_GLSL

// A point of cell `cell`'s square (`corner`: 0..1 across, 0..1 up) as a
// texture coordinate of the whole atlas (before textureCoordinate, which
// flips v).
vec2 impostorAtlasCoordinate(int cell, int cells, vec2 corner) {
  vec2 origin = vec2(float(cell % cells), float(cell / cells));
  return vec2((origin.x + corner.x) / float(cells), 1.0 - (origin.y + 1.0 - corner.y) / float(cells));
}

// The height above the cell's plane, in half sides of the quad (-1..1),
// that a normal map texel's alpha holds (impostor_capture.frag's encoding).
float impostorHeight(float alpha) {
  return ((alpha * 255.0 - 1.0) / 254.0) * 2.0 - 1.0;
}
#endif
