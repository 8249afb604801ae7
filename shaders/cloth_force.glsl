// The force rule both GPU steps share (sim/forces/force_field.cpp add_body_forces,
// sim/forces/spring_forces.hpp): included after wind_gust.glsl by the compute step
// (cloth_step.comp) and the transform-feedback step (cloth_step_tf.vert). Every term is written
// out in the CPU's order and `precise`, so no multiply-add is fused and the results can match
// the CPU bit for bit. With wind it reads the surface (unit normal, vertex area) made from the
// same positions just before.
//
// CLOTH_WIND 0 compiles the wind out (the transform-feedback step's program for a calm scene):
// llvmpipe pays for a branch on a uniform as if both sides ran.
#ifndef CLOTH_WIND
#define CLOTH_WIND 1
#endif

// Model: the padded slot-major neighbour table (slot s of vertex i at s * n + i) and its springs.
layout(binding = 0) uniform isamplerBuffer neighbour;
layout(binding = 1) uniform samplerBuffer stiffness;    // N/m, 0 on padding
layout(binding = 2) uniform samplerBuffer rest_length;  // m
layout(binding = 3) uniform samplerBuffer damping;      // N s/m
// The state read by the force gather: positions and velocities (xyz, w unused).
layout(binding = 4) uniform samplerBuffer gather_x;
layout(binding = 5) uniform samplerBuffer gather_v;
layout(std430, binding = 6) readonly buffer Mass { float mass[]; };      // kg
layout(std430, binding = 8) readonly buffer Surface { vec4 surface[]; };  // (unit n, area m^2)

uniform uint n;
uniform int slots;
uniform bool damped;
uniform vec3 gravity;  // m/s^2
uniform float drag;    // N s/m
// Wind (sim/forces/wind.hpp): F = coefficient A ((k W - v) . n) n with the gust factor
// k = 1 + gust g((t - x . lag) / period), lag = W / |W|^2.
uniform bool windy;
uniform bool gusty;
uniform vec3 wind;               // m/s, mean wind W
uniform float wind_coefficient;  // kg/(m^2 s)
uniform double t;                // s, the time of this force evaluation
uniform dvec3 wind_lag;          // s/m
uniform double gust;
uniform double gust_period;  // s
uniform uvec2 gust_seeds[2];

float gust_factor(vec3 x) {
  if (!gusty) return 1.0;
  precise double along = double(x.x) * wind_lag.x + double(x.y) * wind_lag.y +
                         double(x.z) * wind_lag.z;
  precise double s = (t - along) / gust_period;
  precise double k = 1.0LF + gust * gust_noise(gust_seeds, s);
  return float(k);
}

// F(x, v) on vertex i from the gather textures: gravity and drag, then each slot's spring in
// slot order. Hooke k (|d| - L) d/|d| plus along-spring damping c ((v_j - v_i) . d) d / |d|^2.
vec3 total_force(uint i) {
  const vec3 xi = texelFetch(gather_x, int(i)).xyz;
  const vec3 vi = texelFetch(gather_v, int(i)).xyz;
  const float mi = mass[i];
  precise float fx = mi * gravity.x - drag * vi.x;
  precise float fy = mi * gravity.y - drag * vi.y;
  precise float fz = mi * gravity.z - drag * vi.z;
  for (int s = 0; s < slots; ++s) {
    const int e = s * int(n) + int(i);
    const int j = texelFetch(neighbour, e).r;
    const vec3 xj = texelFetch(gather_x, j).xyz;
    precise float dx = xj.x - xi.x;
    precise float dy = xj.y - xi.y;
    precise float dz = xj.z - xi.z;
    precise float len = sqrt(dx * dx + dy * dy + dz * dz);
    // Padding (j == i) has len = 0 and k = 0: the select keeps it at zero force.
    precise float inv_len = len > 0.0 ? 1.0 / len : 0.0;
    precise float scale = texelFetch(stiffness, e).r * (len - texelFetch(rest_length, e).r) * inv_len;
    if (damped) {
      const vec3 vj = texelFetch(gather_v, j).xyz;
      precise float rvx = vj.x - vi.x;
      precise float rvy = vj.y - vi.y;
      precise float rvz = vj.z - vi.z;
      scale += texelFetch(damping, e).r * (rvx * dx + rvy * dy + rvz * dz) * inv_len * inv_len;
    }
    fx += scale * dx;
    fy += scale * dy;
    fz += scale * dz;
  }
#if CLOTH_WIND
  if (windy) {
    const vec4 sn = surface[i];
    const float k = gust_factor(xi);
    precise float normal_speed = (wind.x * k - vi.x) * sn.x + (wind.y * k - vi.y) * sn.y +
                                 (wind.z * k - vi.z) * sn.z;
    precise float scale = wind_coefficient * sn.w * normal_speed;
    fx += scale * sn.x;
    fy += scale * sn.y;
    fz += scale * sn.z;
  }
#endif
  return vec3(fx, fy, fz);
}
