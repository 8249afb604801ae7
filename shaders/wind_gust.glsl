// The wind's gust factor on the GPU: sim/forces/wind.hpp's seeded two-octave value noise, term by
// term in double precision, so a gusty wind blows the same on both backends. GLSL 4.5 core has no
// 64-bit integers, so SplitMix64's finaliser runs on uvec2(low, high) words with umulExtended.

uvec2 add64(uvec2 a, uvec2 b) {
  uint carry;
  const uint lo = uaddCarry(a.x, b.x, carry);
  return uvec2(lo, a.y + b.y + carry);
}

// a * b mod 2^64.
uvec2 mul64(uvec2 a, uvec2 b) {
  uint hi, lo;
  umulExtended(a.x, b.x, hi, lo);
  return uvec2(lo, hi + a.x * b.y + a.y * b.x);
}

// z ^ (z >> s) for 0 < s < 32.
uvec2 xor_shift(uvec2 z, int s) {
  return z ^ uvec2((z.x >> s) | (z.y << (32 - s)), z.y >> s);
}

uvec2 splitmix(uvec2 z) {
  z = mul64(xor_shift(z, 30), uvec2(0x1ce4e5b9u, 0xbf58476du));
  z = mul64(xor_shift(z, 27), uvec2(0x133111ebu, 0x94d049bbu));
  return xor_shift(z, 31);
}

// detail::lattice_value: seed_golden is seed * 0x9e3779b97f4a7c15 (made on the CPU).
double lattice_value(uvec2 seed_golden, int cell) {
  const uvec2 h = splitmix(add64(seed_golden, uvec2(uint(cell), cell < 0 ? 0xffffffffu : 0u)));
  // h >> 11 has 53 bits: exact in a double.
  const double top = double(h.y >> 11u) * 4294967296.0LF + double((h.x >> 11u) | (h.y << 21u));
  return top * (2.0LF / 9007199254740992.0LF) - 1.0LF;
}

double value_noise(uvec2 seed_golden, double s) {
  const double cell = floor(s);
  precise double f = s - cell;
  precise double w = f * f * f * (f * (f * 6.0LF - 15.0LF) + 10.0LF);  // Perlin's quintic fade
  const int c = int(cell);
  const double a = lattice_value(seed_golden, c), b = lattice_value(seed_golden, c + 1);
  precise double r = a + (b - a) * w;
  return r;
}

// gust_noise(seed, s): seeds[0] for seed, seeds[1] for seed + 1.
double gust_noise(uvec2 seeds[2], double s) {
  precise double second = 2.17LF * s + 0.5LF;
  precise double g = (2.0LF / 3.0LF) * value_noise(seeds[0], s) +
                     (1.0LF / 3.0LF) * value_noise(seeds[1], second);
  return g;
}
