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

// The page of a level holding texel position `texel` (continuous, texel centres at .5), among pages [low, high].
ivec2 pageAt(vec2 texel, ivec2 low, ivec2 high) { return clamp(ivec2(floor(texel / float(kPagePayload))), low, high); }

// The pages a sample of a level `levelSize` texels across may take: all of them, or with face >= 0 those of
// one face of a HEALPix pyramid (strata/healpix_pyramid.hpp: faces side by side, each levelSize.y across),
// so that a point on a face's edge is filtered in its own face's page, whose border holds the texels of the
// neighbouring face on the sphere, and not in the page of the next face along the strip.
void pageRange(ivec2 levelSize, int face, out ivec2 low, out ivec2 high) {
  if (face < 0) {
    low = ivec2(0);
    high = (levelSize - 1) / kPagePayload;
    return;
  }
  int pages = levelSize.y / kPagePayload;
  low = ivec2(face * pages, 0);
  high = ivec2(face * pages + pages - 1, pages - 1);
}

// The value at level-0 texel position `texel0` on pyramid level `level`, filtered bilinearly by hand
// within one slot: the border makes the four texels always lie in it. Texel fetches, not the sampler's
// filtering: llvmpipe gave one vertex different filtered values in different invocations (see
// surface_point.glsl), and the atlas has no neighbours to filter across anyway. Where the page is not
// loaded, the coarser page its index entry references is sampled instead; where nothing is, vec4(0).
// `face`: as pageRange.
vec4 samplePagedLevel(sampler2DArray atlas, uint indexBase, ivec2 size, int level, vec2 texel0, int face) {
  ivec2 levelSize = pagedLevelSize(size, level), low, high;
  pageRange(levelSize, face, low, high);
  ivec2 page = pageAt(texel0 / float(1 << level), low, high);
  uint entry = pageIndexEntry(pageIndexEntry(indexBase + uint(level)) +
                              uint(page.y * ((levelSize.x + kPagePayload - 1) / kPagePayload) + page.x));
  if (entry == 0u) return vec4(0.0);
  int held = int((entry >> 16) & 31u);
  vec2 texel = texel0 / float(1 << held);
  pageRange(pagedLevelSize(size, held), face, low, high);
  page = pageAt(texel, low, high);
  // Slot texel positions, centres at integers: level texel j of the page is slot texel j + 1.
  vec2 position = texel - vec2(page * kPagePayload) + 0.5;
  ivec2 corner = clamp(ivec2(floor(position)), ivec2(0), ivec2(kPagePayload));
  vec2 f = clamp(position - vec2(corner), 0.0, 1.0);
  int slot = int(entry & 0xffffu);
  return mix(mix(texelFetch(atlas, ivec3(corner, slot), 0), texelFetch(atlas, ivec3(corner.x + 1, corner.y, slot), 0), f.x),
             mix(texelFetch(atlas, ivec3(corner.x, corner.y + 1, slot), 0), texelFetch(atlas, ivec3(corner + 1, slot), 0), f.x),
             f.y);
}

// Trilinear sampling across levels (seed 000 section 4.3.2 "a shader implementation of trilinear
// mipmapping") at level-0 texel position `texel0`, the level chosen from the footprint: level-0 texels to
// the next sample. `face`: as pageRange.
vec4 samplePagedTexels(sampler2DArray atlas, uint indexBase, int levels, ivec2 size, vec2 texel0, float footprint,
                       int face) {
  float lod = clamp(log2(footprint), 0.0, float(levels - 1));
  int level = int(floor(lod));
  vec4 fine = samplePagedLevel(atlas, indexBase, size, level, texel0, face);
  if (level + 1 >= levels || fract(lod) == 0.0) return fine;
  return mix(fine, samplePagedLevel(atlas, indexBase, size, level + 1, texel0, face), fract(lod));
}

// The same at texture coordinates `uv` (0..1 over the raster), the footprint given as their steps to the next
// sample.
vec4 samplePaged(sampler2DArray atlas, uint indexBase, int levels, ivec2 size, vec2 uv, vec2 stepX, vec2 stepY,
                 bool repeatX) {
  if (repeatX) uv.x = fract(uv.x);
  vec2 texels = vec2(size);
  return samplePagedTexels(atlas, indexBase, levels, size, uv * texels,
                           max(length(stepX * texels), length(stepY * texels)), -1);
}
