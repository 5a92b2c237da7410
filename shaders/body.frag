#version 330 core
// The avatar: a matte skin-like surface lit by a head light and a fill light.

in vec3 view_position;
in vec3 view_normal;

uniform vec3 base_colour;
uniform float opacity;  // below 1: the body seen through

out vec4 colour;

void main() {
  vec3 n = normalize(view_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 to_eye = normalize(-view_position);
  vec3 key = normalize(vec3(0.35, 0.6, 1.0));
  vec3 fill = normalize(vec3(-0.6, -0.2, 0.5));
  float diffuse = 0.7 * max(dot(n, key), 0.0) + 0.25 * max(dot(n, fill), 0.0);
  float specular = 0.15 * pow(max(dot(n, normalize(key + to_eye)), 0.0), 24.0);
  colour = vec4(base_colour * (0.22 + diffuse) + vec3(specular), opacity);
}
