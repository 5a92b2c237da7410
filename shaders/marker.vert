#version 330 core
// Body location markers: points at the centres and short segments along the axes, coloured per vertex.

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 vertex_colour;

uniform mat4 model_view;
uniform mat4 projection;
uniform float point_size;

out vec3 marker_colour;

void main() {
  marker_colour = vertex_colour;
  gl_PointSize = point_size;
  gl_Position = projection * model_view * vec4(position, 1.0);
}
