#version 450 core
#include "frame.glsl"

// Flat normals for the transform-feedback backend (gpu/tf_cloth.hpp), whose captured positions
// are drawn as they are: each triangle's unit normal normalize((x1 - x0) x (x2 - x0)), written
// out term by term and `precise` as the CPU's face normal, given to its three corners, so the
// lit modes and mode 2's normal colours shade every triangle flat. Passes the other varyings of
// cloth.vert through (defined with FLAT_NORMALS, which renames them vg_*).
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vg_world[];
in vec3 vg_normal[];  // unused: cloth.vert's attribute, not meaningful on this backend
in vec2 vg_uv[];
in float vg_scalar[];
in vec4 vg_tangent[];
in vec2 vg_atlas_uv[];

out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out float v_scalar;
out vec4 v_tangent;
out vec2 v_atlas_uv;
#if SHADOW_FAST_COORD
out vec4 v_shadow_clip;
#endif

vec3 face_normal(vec3 p0, vec3 p1, vec3 p2) {
  precise float ax = p1.x - p0.x, ay = p1.y - p0.y, az = p1.z - p0.z;
  precise float bx = p2.x - p0.x, by = p2.y - p0.y, bz = p2.z - p0.z;
  precise float cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
  precise float len = sqrt(cx * cx + cy * cy + cz * cz);
  return len > 0.0 ? vec3(cx / len, cy / len, cz / len) : vec3(0.0);
}

void main() {
  const vec3 n = face_normal(vg_world[0], vg_world[1], vg_world[2]);
  for (int k = 0; k < 3; ++k) {
    v_world = vg_world[k];
    v_normal = n;
    v_uv = vg_uv[k];
    v_scalar = vg_scalar[k];
    v_tangent = vg_tangent[k];
    v_atlas_uv = vg_atlas_uv[k];
#if SHADOW_FAST_COORD
    v_shadow_clip = shadow_clip_vertex(vg_world[k], n);
#endif
    gl_Position = gl_in[k].gl_Position;
    EmitVertex();
  }
  EndPrimitive();
}
