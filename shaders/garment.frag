#version 330 core
// Garment pieces, lit on both sides. Triangles wind counter-clockwise seen from the garment's outside,
// so gl_FrontFacing tells which side the viewer sees: the outside colour or the inside colour. A
// flipped piece shows its inside colour where its neighbours show their outside. With the strain map
// on, both sides take the colour of the strain instead; waiting pieces fade towards the background;
// the wireframe pass draws the edges in one flat colour.

in vec3 view_position;
in vec3 view_normal;
in float vertex_strain;

uniform vec3 outside_colour;
uniform vec3 inside_colour;
uniform vec3 highlight_colour;
uniform float highlight;  // 0 normal, > 0 selected piece
uniform vec3 fade_colour;
uniform float fade;  // 0 normal, > 0 waiting piece
uniform bool strain_map;
uniform vec3 strain_stops[4];  // colours at 0, 1/3, 2/3 and 1 of strain_full_scale
uniform float strain_full_scale;
uniform bool wire;
uniform vec3 wire_colour;

out vec4 colour;

vec3 strain_colour(float strain) {
  float t = 3.0 * clamp(strain / strain_full_scale, 0.0, 1.0);
  int stop = min(int(t), 2);
  return mix(strain_stops[stop], strain_stops[stop + 1], t - float(stop));
}

void main() {
  if (wire) {
    colour = vec4(wire_colour, 1.0);
    return;
  }
  vec3 n = normalize(view_normal);
  vec3 base = outside_colour;
  if (!gl_FrontFacing) {
    n = -n;
    base = inside_colour;
  }
  if (strain_map) base = strain_colour(vertex_strain);
  base = mix(base, highlight_colour, highlight);
  vec3 to_eye = normalize(-view_position);
  vec3 key = normalize(vec3(0.35, 0.6, 1.0));
  vec3 fill = normalize(vec3(-0.6, -0.2, 0.5));
  float diffuse = 0.7 * max(dot(n, key), 0.0) + 0.25 * max(dot(n, fill), 0.0);
  float specular = 0.08 * pow(max(dot(n, normalize(key + to_eye)), 0.0), 16.0);
  colour = vec4(mix(base * (0.25 + diffuse) + vec3(specular), fade_colour, fade), 1.0);
}
