#version 330 core
// Layout-tab scene: world-space positions, per-vertex colour, world-space normal (zero = unlit).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_colour;
layout(location = 2) in vec3 a_normal;

uniform mat4 u_view_projection;

out vec4 v_colour;
out vec3 v_normal;

void main() {
  v_colour = a_colour;
  v_normal = a_normal;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
