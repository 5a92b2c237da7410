#version 330 core
// Body and garment surfaces: positions and normals to view space for lighting in the fragment shader,
// and the garment's per-vertex strain for the strain map (the body has none: the attribute's default).

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in float strain;

uniform mat4 model_view;
uniform mat4 projection;

out vec3 view_position;
out vec3 view_normal;
out float vertex_strain;

void main() {
  vec4 p = model_view * vec4(position, 1.0);
  view_position = p.xyz;
  // The scene is only rotated and translated (no scaling), so the model-view matrix maps normals too.
  view_normal = mat3(model_view) * normal;
  vertex_strain = strain;
  gl_Position = projection * p;
}
