// A level-0 texel position (continuous, texel centres at .5) as a whole texel and a part: float alone resolves
// 2^-24 of a raster's width, a quarter texel of the 4.3 million texels of a global 5 m map of Mars, so the
// whole texel is an integer, from the CPU's double where the point is near the eye (docs/architecture.md,
// "Precision"; ProjectedRasterLayer::setReference), and the part a small float beside it.
struct TexelAddress {
  ivec2 whole;
  vec2 part;
};

// A position known only as a float: no finer than it was.
TexelAddress texelAddressOf(vec2 texel) {
  vec2 whole = floor(texel);
  return TexelAddress(ivec2(whole), texel - whole);
}

// Texels from `address` to the raster's west, north, east and south edges (`size` texels across and down):
// the whole texels' differences are exact, so a point near an edge has its distance to a fraction of a texel.
vec4 edgeDistances(TexelAddress address, ivec2 size) {
  vec2 fromStart = vec2(address.whole) + address.part, toEnd = vec2(size - address.whole) - address.part;
  return vec4(fromStart, toEnd);
}
