#version 450
// One triangle from the vertex index: no vertex buffer.
void main() {
  const vec2 corners[3] = vec2[](vec2(0.0, -0.6), vec2(0.6, 0.6), vec2(-0.6, 0.6));
  gl_Position = vec4(corners[gl_VertexIndex], 0.0, 1.0);
}
