#version 330 core
// Round points (square point sprites with the corners cut), plain lines.

in vec3 marker_colour;

uniform bool round_points;

out vec4 colour;

void main() {
  if (round_points) {
    vec2 from_centre = gl_PointCoord - vec2(0.5);
    if (dot(from_centre, from_centre) > 0.25) discard;
  }
  colour = vec4(marker_colour, 1.0);
}
