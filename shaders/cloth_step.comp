#version 450 core
// One stage of a cloth step on the GPU (gpu/gpu_cloth.cpp), one invocation per vertex: the
// CPU's force rule (cloth_force.glsl) and integrators (sim/integrators/symplectic_euler.cpp,
// verlet.cpp), written out term by term in the CPU's order and `precise`, so no multiply-add is
// fused and the results can match bit for bit.
//   stage 0: symplectic Euler, v' = v + h f(x, v)/m, x' = x + h v'   (x_in, v_in -> x_out, v_out)
//   stage 1: force only, f = F(x_in, v_in)                           (Verlet's first evaluation)
//   stage 2: Verlet kick and drift with the stored f                 (-> x_out, v_out, v_pred)
//   stage 3: Verlet end force F(x_out, v_pred) and the second kick   (-> force, v_out)
// Neighbours are gathered through buffer textures (texelFetch), the same buffers the SSBOs hold.
// With wind, each force evaluation reads the surface (unit normal, vertex area) that
// cloth_faces.comp and cloth_normals.comp made from the same positions just before.
layout(local_size_x = 64) in;

#include "wind_gust.glsl"
#include "cloth_force.glsl"

layout(std430, binding = 0) readonly buffer XIn { vec4 x_in[]; };
layout(std430, binding = 1) readonly buffer VIn { vec4 v_in[]; };
layout(std430, binding = 2) buffer XOut { vec4 x_out[]; };
layout(std430, binding = 3) buffer VOut { vec4 v_out[]; };
layout(std430, binding = 4) buffer Force { vec4 force[]; };  // N, Verlet's stored force
layout(std430, binding = 5) buffer VPred { vec4 v_pred[]; };  // Verlet's predicted velocity
layout(std430, binding = 7) readonly buffer InvMass { float inv_mass[]; };  // 1/kg, 0 pinned

uniform int stage;
uniform float h;       // s
uniform float half_h;  // 0.5 h, rounded as the CPU rounds it

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= n) return;
  const float im = inv_mass[i];
  if (stage == 0) {
    const vec3 f = total_force(i);
    precise vec3 a = f * im;
    precise vec3 v = v_in[i].xyz + h * a;
    precise vec3 x = x_in[i].xyz + h * v;
    v_out[i] = vec4(v, 0.0);
    x_out[i] = vec4(x, 0.0);
  } else if (stage == 1) {
    force[i] = vec4(total_force(i), 0.0);
  } else if (stage == 2) {
    precise vec3 kick = half_h * force[i].xyz * im;
    precise vec3 v = v_in[i].xyz + kick;
    precise vec3 x = x_in[i].xyz + h * v;
    precise vec3 vp = v + kick;
    v_out[i] = vec4(v, 0.0);
    x_out[i] = vec4(x, 0.0);
    v_pred[i] = vec4(vp, 0.0);
  } else {
    const vec3 f = total_force(i);
    force[i] = vec4(f, 0.0);
    precise vec3 v = v_out[i].xyz + half_h * f * im;
    v_out[i] = vec4(v, 0.0);
  }
}
