#version 450 core
// One substep of the cloth as a draw (gpu/tf_cloth.cpp): vertex i of a GL_POINTS draw of the
// cloth's n vertices, rasterisation discarded, gathers its springs with the force rule the compute
// step uses (cloth_force.glsl) and writes its new position and velocity as outputs that transform
// feedback captures into the other buffers of the ping-pong pair. The integrators are the CPU's
// one-evaluation rules (sim/integrators/symplectic_euler.cpp, explicit_euler.cpp, seed_hack.cpp),
// term by term in the CPU's order and `precise`:
//   TF_RULE 0: symplectic Euler  v' = v + h a,  x' = x + h v'
//   TF_RULE 1: explicit Euler    x' = x + h v,  v' = v + h a
//   TF_RULE 2: the seed hack     dv = a h,  x' = x + (v + dv) h + 0.5 a h h,  v' = v + dv
// with a = f(x, v) / m (0 on pinned vertices, whose inverse mass is 0). The rule is a compile-time
// choice (TF_RULE), as is the wind (CLOTH_WIND): llvmpipe pays for a branch on a uniform as if
// both sides ran.

#include "wind_gust.glsl"
#include "cloth_force.glsl"

layout(std430, binding = 7) readonly buffer InvMass { float inv_mass[]; };  // 1/kg, 0 pinned

uniform float h;  // s

out vec4 x_out;  // m, captured into the other position buffer
out vec4 v_out;  // m/s, captured into the other velocity buffer

void main() {
  const uint i = uint(gl_VertexID);
  const vec3 f = total_force(i);
  precise vec3 a = f * inv_mass[i];
  precise vec3 x = texelFetch(gather_x, int(i)).xyz;
  precise vec3 v = texelFetch(gather_v, int(i)).xyz;
#if TF_RULE == 0
  v = v + h * a;
  x = x + h * v;
#elif TF_RULE == 1
  x = x + h * v;
  v = v + h * a;
#else
  precise vec3 dv = a * h;
  x = x + ((v + dv) * h + 0.5 * a * h * h);
  v = v + dv;
#endif
  x_out = vec4(x, 0.0);
  v_out = vec4(v, 0.0);
}
