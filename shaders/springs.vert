#version 450 core

layout(location = 0) in vec3 position;
layout(location = 3) in vec3 rest_position;

out vec3 g_position;
out vec3 g_rest;

void main() {
  g_position = position;
  g_rest = rest_position;
}
