#version 330 core
// Body and garment surfaces: positions and normals to view space for lighting in the fragment shader.

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 model_view;
uniform mat4 projection;

out vec3 view_position;
out vec3 view_normal;

void main() {
  vec4 p = model_view * vec4(position, 1.0);
  view_position = p.xyz;
  // The scene is only rotated and translated (no scaling), so the model-view matrix maps normals too.
  view_normal = mat3(model_view) * normal;
  gl_Position = projection * p;
}
