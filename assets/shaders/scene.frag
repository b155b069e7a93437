#version 330 core
// Two lights: a headlight along the view direction and a soft sky light from above, so boxes
// read as solids from every orbit angle. Unlit when the normal is zero (lines, labels).
in vec4 v_colour;
in vec3 v_normal;

uniform vec3 u_view_dir;  // world, from the eye into the scene

out vec4 frag_colour;

void main() {
  float n_len = length(v_normal);
  if (n_len < 1e-4) {
    frag_colour = v_colour;
    return;
  }
  vec3 n = v_normal / n_len;
  float head = abs(dot(n, -u_view_dir));
  float sky = 0.5 + 0.5 * n.y;
  float light = 0.35 + 0.45 * head + 0.25 * sky;
  frag_colour = vec4(v_colour.rgb * light, v_colour.a);
}
