#version 330 core
// Writes the object id (0 = nothing, 1 = body, 2 + i = garment piece i) as 24 bits of RGB.

uniform int object_id;

out vec4 colour;

void main() {
  colour = vec4(float(object_id & 255), float((object_id >> 8) & 255), float((object_id >> 16) & 255),
                255.0) / 255.0;
}
