#version 330 core
// Garment pieces, lit on both sides. Triangles wind counter-clockwise seen from the garment's outside,
// so gl_FrontFacing tells which side the viewer sees: the outside colour or the inside colour. A
// flipped piece shows its inside colour where its neighbours show their outside.

in vec3 view_position;
in vec3 view_normal;

uniform vec3 outside_colour;
uniform vec3 inside_colour;
uniform vec3 highlight_colour;
uniform float highlight;  // 0 normal, > 0 selected piece

out vec4 colour;

void main() {
  vec3 n = normalize(view_normal);
  vec3 base = outside_colour;
  if (!gl_FrontFacing) {
    n = -n;
    base = inside_colour;
  }
  base = mix(base, highlight_colour, highlight);
  vec3 to_eye = normalize(-view_position);
  vec3 key = normalize(vec3(0.35, 0.6, 1.0));
  vec3 fill = normalize(vec3(-0.6, -0.2, 0.5));
  float diffuse = 0.7 * max(dot(n, key), 0.0) + 0.25 * max(dot(n, fill), 0.0);
  float specular = 0.08 * pow(max(dot(n, normalize(key + to_eye)), 0.0), 16.0);
  colour = vec4(base * (0.25 + diffuse) + vec3(specular), 1.0);
}
