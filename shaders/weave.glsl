// The weave's relief (key 6) for the fragment shaders that light the cloth: its tangent-space
// normal map (vis/textures/weave_maps.hpp) in the per-vertex tangent frame (T along +u,
// B = w N x T along +v, Gram-Schmidt against the interpolated normal). Bytes decode as
// b * 255/127 - 128/127, so 128 is exactly 0 and a flat map gives N itself.
layout(binding = 3) uniform sampler2D u_weave_normals;  // linear bytes

// The relief's normal on the front side (n_front: the interpolated front normal).
vec3 weave_normal_front(vec3 n_front, vec4 tangent, vec2 uv) {
  vec3 t = normalize(tangent.xyz - n_front * dot(n_front, tangent.xyz));
  vec3 b = (tangent.w < 0.0 ? -1.0 : 1.0) * cross(n_front, t);
  vec3 m = texture(u_weave_normals, uv).rgb * (255.0 / 127.0) - 128.0 / 127.0;
  return normalize(t * m.x + b * m.y + n_front * m.z);
}
