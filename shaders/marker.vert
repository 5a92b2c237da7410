#version 330 core
// Body location markers (points at the centres and short segments along the axes) and the garment's
// diagnostic lines and points: coloured per vertex, each lifted towards the camera by its own
// distance before the depth test (a marker inside a limb by the limb's radius).

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 vertex_colour;
layout(location = 2) in float lift;  // metres

uniform mat4 model_view;
uniform mat4 projection;
uniform float point_size;

out vec3 marker_colour;

void main() {
  marker_colour = vertex_colour;
  gl_PointSize = point_size;
  vec4 p = model_view * vec4(position, 1.0);
  // Along the view ray towards the eye (the origin of view space): the point keeps its pixel.
  float eye_distance = length(p.xyz);
  if (eye_distance > lift) p.xyz *= (eye_distance - lift) / eye_distance;
  gl_Position = projection * p;
}
