#version 450 core

// Depth only: the shadow map keeps gl_FragCoord.z.
void main() {}
