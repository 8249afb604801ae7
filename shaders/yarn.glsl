// Light through a dyed thread (mode 5): the dye absorbs the colours the thread does not reflect
// and lets its own through nearly whole, so the transmitted colour is the albedo's chromaticity
// at full brightness (the albedo over its largest channel), times the thread's transmission.
// Light scattered back is what makes the albedo dark; light passing through is not darkened by
// it. Linear RGB in, linear RGB out.
vec3 yarn_filter(vec3 albedo) {
  return albedo / max(max(albedo.r, max(albedo.g, albedo.b)), 1e-4);
}
