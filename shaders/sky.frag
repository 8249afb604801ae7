#version 450 core

// The sky cube map along the camera ray through this pixel: the pixel's far-plane point from
// the inverse view-projection, minus the eye. Linear radiance; the framebuffer encodes sRGB.
layout(location = 0) uniform mat4 u_inverse_view_proj;
layout(location = 1) uniform vec3 u_eye;
layout(binding = 0) uniform samplerCube u_sky;

in vec2 v_ndc;
out vec4 color;

void main() {
  vec4 far = u_inverse_view_proj * vec4(v_ndc, 1.0, 1.0);
  vec3 direction = normalize(far.xyz / far.w - u_eye);
  color = vec4(texture(u_sky, direction).rgb, 1.0);
}
