// Virtual texturing through the page cache (seed 000 section 4.3.2; core/src/paging). A layer's pages
// sit in an atlas (a 2D array texture of 514x514 slots: 512 texels and a 1-texel border) and the index
// of page references, shared by every layer, says which slot holds each page of each level, or which
// coarser page stands in for it (core/src/paging/page_index.hpp gives the layout).
uniform usampler2D strata_pageIndex;

const int kPageIndexWidth = 4096;
const int kPagePayload = 512;

uint pageIndexEntry(uint i) {
  return texelFetch(strata_pageIndex, ivec2(int(i % uint(kPageIndexWidth)), int(i / uint(kPageIndexWidth))), 0).r;
}

// Texels of a level: the raster's size / 2^level, rounded up, as PagePyramid has it.
ivec2 pagedLevelSize(ivec2 size, int level) { return (size + (1 << level) - 1) >> level; }

// The page of `level` holding texel position `texel` (continuous, texel centres at .5).
ivec2 pageAt(vec2 texel, ivec2 levelSize) {
  return clamp(ivec2(floor(texel / float(kPagePayload))), ivec2(0), (levelSize - 1) / kPagePayload);
}

// The value at `uv` (0..1 over the raster) on pyramid level `level`, filtered bilinearly by hand
// within one slot: the border makes the four texels always lie in it. Texel fetches, not the sampler's
// filtering: llvmpipe gave one vertex different filtered values in different invocations (see
// surface_point.glsl), and the atlas has no neighbours to filter across anyway. Where the page is not
// loaded, the coarser page its index entry references is sampled instead; where nothing is, vec4(0).
vec4 samplePagedLevel(sampler2DArray atlas, uint indexBase, ivec2 size, int level, vec2 uv) {
  ivec2 levelSize = pagedLevelSize(size, level);
  ivec2 page = pageAt(uv * vec2(size) / float(1 << level), levelSize);
  uint entry = pageIndexEntry(pageIndexEntry(indexBase + uint(level)) +
                              uint(page.y * ((levelSize.x + kPagePayload - 1) / kPagePayload) + page.x));
  if (entry == 0u) return vec4(0.0);
  int held = int((entry >> 16) & 31u);
  vec2 texel = uv * vec2(size) / float(1 << held);
  page = pageAt(texel, pagedLevelSize(size, held));
  // Slot texel positions, centres at integers: level texel j of the page is slot texel j + 1.
  vec2 position = texel - vec2(page * kPagePayload) + 0.5;
  ivec2 low = clamp(ivec2(floor(position)), ivec2(0), ivec2(kPagePayload));
  vec2 f = clamp(position - vec2(low), 0.0, 1.0);
  int slot = int(entry & 0xffffu);
  return mix(mix(texelFetch(atlas, ivec3(low, slot), 0), texelFetch(atlas, ivec3(low.x + 1, low.y, slot), 0), f.x),
             mix(texelFetch(atlas, ivec3(low.x, low.y + 1, slot), 0), texelFetch(atlas, ivec3(low + 1, slot), 0), f.x),
             f.y);
}

// Trilinear sampling across levels (seed 000 section 4.3.2 "a shader implementation of trilinear
// mipmapping"), the level chosen from the footprint: texture-coordinate steps to the next sample.
vec4 samplePaged(sampler2DArray atlas, uint indexBase, int levels, ivec2 size, vec2 uv, vec2 stepX, vec2 stepY,
                 bool repeatX) {
  if (repeatX) uv.x = fract(uv.x);
  vec2 texels = vec2(size);
  float lod = clamp(log2(max(length(stepX * texels), length(stepY * texels))), 0.0, float(levels - 1));
  int level = int(floor(lod));
  vec4 fine = samplePagedLevel(atlas, indexBase, size, level, uv);
  if (level + 1 >= levels || fract(lod) == 0.0) return fine;
  return mix(fine, samplePagedLevel(atlas, indexBase, size, level + 1, uv), fract(lod));
}
