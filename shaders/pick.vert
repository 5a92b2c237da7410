#version 330 core
// Picking pass: only the depth and an object id are drawn.

layout(location = 0) in vec3 position;

uniform mat4 model_view;
uniform mat4 projection;

void main() { gl_Position = projection * model_view * vec4(position, 1.0); }
