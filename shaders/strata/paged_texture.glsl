// Virtual texturing through the page cache ([Kooima 2008, §4.3.2]; core/paging). A layer's pages
// sit in an atlas (a 2D array texture of 514x514 slots: 512 texels and a 1-texel border) and the index
// of page references, shared by every layer, says which slot holds each page of each level, or which
// coarser page stands in for it (core/paging/src/page_index.hpp gives the layout).
#include "strata/anisotropic_taps.glsl"
#include "strata/texel_address.glsl"

uniform usampler2D strata_pageIndex;

const int kPageIndexWidth = 4096;
const int kPagePayload = 512;
const int kPagePayloadBits = 9;  // kPagePayload = 2^9

uint pageIndexEntry(uint i) {
  return texelFetch(strata_pageIndex, ivec2(int(i % uint(kPageIndexWidth)), int(i / uint(kPageIndexWidth))), 0).r;
}

// Texels of a level: the raster's size / 2^level, rounded up, as PagePyramid has it.
ivec2 pagedLevelSize(ivec2 size, int level) { return (size + (1 << level) - 1) >> level; }

// The level texel of `address` on pyramid level `level` (level-0 texels / 2^level): its whole part, and in
// `part` what lies beyond it, in [0, 1). Integer shifts divide the whole texel, so it keeps every digit.
ivec2 levelTexel(TexelAddress address, int level, out vec2 part) {
  vec2 carried = floor(address.part);
  ivec2 whole = address.whole + ivec2(carried);
  ivec2 levelWhole = whole >> level;  // sign-extending: the floor of the quotient
  part = (vec2(whole - (levelWhole << level)) + (address.part - carried)) / float(1 << level);
  return levelWhole;
}

// The page of a level holding level texel `whole`, among pages [low, high].
ivec2 pageAt(ivec2 whole, ivec2 low, ivec2 high) { return clamp(whole >> kPagePayloadBits, low, high); }

// The pages a sample of a level `levelSize` texels across may take: all of them, or with face >= 0 those of
// one face of a HEALPix pyramid (strata/plugin/healpix_pyramid.hpp: faces side by side, each levelSize.y across),
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

// Bilinear filtering within atlas slot `slot` at slot texel position `position` (texel centres at integers): the
// border makes the four texels always lie in the slot. `bySampler`: the sampler filters (a colour atlas, in a
// fragment stage), its 8-bit weights finer than colour shows; else by hand with texel fetches, as heights and
// values need: their differences shade relief, and llvmpipe gave one vertex different filtered values in
// different invocations (see surface_point.glsl). A value page's texels hold the value's slopes per slot texel
// times coverage in .b and .a (page_value_slopes.comp), which filter with it: the four texels' central
// differences mixed bilinearly, continuous across cells.
vec4 slotBilinear(sampler2DArray atlas, vec2 position, int slot, bool bySampler) {
#ifndef STRATA_GEOMETRY_STAGE
  if (bySampler) return textureLod(atlas, vec3((position + 0.5) / float(kPagePayload + 2), float(slot)), 0.0);
#endif
  ivec2 corner = clamp(ivec2(floor(position)), ivec2(0), ivec2(kPagePayload));
  vec2 f = clamp(position - vec2(corner), 0.0, 1.0);
  return mix(mix(texelFetch(atlas, ivec3(corner, slot), 0), texelFetch(atlas, ivec3(corner.x + 1, corner.y, slot), 0), f.x),
             mix(texelFetch(atlas, ivec3(corner.x, corner.y + 1, slot), 0), texelFetch(atlas, ivec3(corner + 1, slot), 0), f.x),
             f.y);
}

// The value at level-0 texel `address` on pyramid level `level`, filtered bilinearly within one slot
// (slotBilinear); a value page's slopes in .b and .a per level-0 texel (`bySampler` false: value pages). Where
// the page is not loaded, the coarser page its index entry references is sampled instead; where nothing is,
// vec4(0). `levelStart`: where the level's entries start in the index. `face`: as pageRange.
vec4 samplePagedLevel(sampler2DArray atlas, bool bySampler, uint levelStart, ivec2 size, int level,
                      TexelAddress address, int face) {
  ivec2 levelSize = pagedLevelSize(size, level), low, high;
  pageRange(levelSize, face, low, high);
  vec2 part;
  ivec2 page = pageAt(levelTexel(address, level, part), low, high);
  uint entry = pageIndexEntry(levelStart + uint(page.y * ((levelSize.x + kPagePayload - 1) / kPagePayload) + page.x));
  if (entry == 0u) return vec4(0.0);
  int held = int((entry >> 16) & 31u);
  ivec2 whole = levelTexel(address, held, part);
  pageRange(pagedLevelSize(size, held), face, low, high);
  page = pageAt(whole, low, high);
  // Slot texel positions, centres at integers: level texel j of the page is slot texel j + 1. The whole
  // texels' difference is exact, and small: the position is a float of a page's size.
  vec2 position = vec2(whole - page * kPagePayload) + part + 0.5;
  vec4 texel = slotBilinear(atlas, position, int(entry & 0xffffu), bySampler);
  if (!bySampler) texel.ba /= float(1 << held);  // a value page's slopes: per level-0 texel
  return texel;
}

// The levels a footprint `footprint` level-0 texels wide samples ([Kooima 2008, §4.3.2]: "a shader implementation
// of trilinear mipmapping"): the finer, the coarser's weight (0: the finer alone), and where each starts in the
// index, read once for every tap of an anisotropic footprint.
struct PagedLevels {
  int level;
  float coarser;
  uint fineStart;
  uint coarseStart;
};

PagedLevels pagedLevels(uint indexBase, int levels, float footprint) {
  float lod = clamp(log2(footprint), 0.0, float(levels - 1));
  int level = int(floor(lod));
  float coarser = level + 1 < levels ? fract(lod) : 0.0;
  return PagedLevels(level, coarser, pageIndexEntry(indexBase + uint(level)),
                     coarser > 0.0 ? pageIndexEntry(indexBase + uint(level + 1)) : 0u);
}

// Trilinear sampling across `levels` at level-0 texel `address`: the finer level, then the coarser where it
// weighs. A do-while rather than a branch: llvmpipe runs both sides of a branch, masked, whatever the lanes
// take, but leaves a loop as soon as no lane goes on, so a magnified footprint samples one level. `face`: as
// pageRange.
vec4 samplePagedTexels(sampler2DArray atlas, bool bySampler, PagedLevels levels, ivec2 size, TexelAddress address,
                       int face) {
  int last = levels.level + (levels.coarser > 0.0 ? 1 : 0);
  vec4 sum = vec4(0.0);
  int level = levels.level;
  do {
    bool finer = level == levels.level;
    uint start = finer ? levels.fineStart : levels.coarseStart;
    sum += (finer ? 1.0 - levels.coarser : levels.coarser) *
           samplePagedLevel(atlas, bySampler, start, size, level, address, face);
  } while (++level <= last);
  return sum;
}

// `address` taken into the one period [0, width) of a raster around the body.
TexelAddress wrappedAround(TexelAddress address, int width) {
  float carried = floor(address.part.x);
  int x = address.whole.x + int(carried);
  // The periods to take away by a float quotient, which llvmpipe divides for every lane at once where it divides
  // integers one lane at a time; then one period more or less where the quotient rounded across a whole one.
  x -= width * int(floor(float(x) / float(width)));
  address.whole.x = x < 0 ? x + width : (x >= width ? x - width : x);
  address.part.x -= carried;
  return address;
}

// `address` moved onto face `face` of a strip of HEALPix faces `side` texels across each, where it lies off it.
TexelAddress clampedToFace(TexelAddress address, int face, int side) {
  vec2 carried = floor(address.part);
  ivec2 whole = address.whole + ivec2(carried), low = ivec2(face * side, 0), high = low + side - 1;
  vec2 part = address.part - carried;
  bvec2 below = lessThan(whole, low), above = greaterThan(whole, high);
  return TexelAddress(clamp(whole, low, high), mix(mix(part, vec2(0.0), below), vec2(0.999), above));
}

// The value at level-0 texel `address` over the footprint whose steps to the next sample are `stepX` and `stepY`
// (level-0 texels), filtered anisotropically (strata/anisotropic_taps.glsl). `repeatX`: each tap wraps around the
// body. `faceSide` > 0: the raster is a strip of HEALPix faces that many texels across each, and the taps stay
// on the face of the footprint's centre and its pages, whose borders hold its neighbours on the sphere; the next
// face along the strip is not one.
vec4 samplePagedAnisotropic(sampler2DArray atlas, bool bySampler, uint indexBase, int levels, ivec2 size,
                            TexelAddress address, vec2 stepX, vec2 stepY, bool repeatX, int faceSide) {
  AnisotropicTaps taps = anisotropicTaps(stepX, stepY);
  PagedLevels sampled = pagedLevels(indexBase, levels, taps.width);  // every tap is as wide
  int face = faceSide > 0 ? (address.whole.x + int(floor(address.part.x))) / faceSide : -1;
  vec4 sum = vec4(0.0);
  int tap = 0;
  do {  // do-while: llvmpipe runs a loop's body once more, masked, when its test comes first
    TexelAddress at = address;
    at.part += tapOffset(taps, tap);
    if (repeatX) at = wrappedAround(at, size.x);
    if (face >= 0) at = clampedToFace(at, face, faceSide);
    sum += samplePagedTexels(atlas, bySampler, sampled, size, at, face);
  } while (++tap < taps.count);
  return sum / float(taps.count);
}

// The same for a raster's own texels, the footprint given as texture coordinates' steps to the next sample;
// a raster around the body (`repeatX`) wraps the address into its one period. Fragment stages filter
// anisotropically (`faceSide`: as samplePagedAnisotropic's); geometry stages (heights for vertices)
// trilinearly at the longer step, their spacing. `bySampler`: as slotBilinear's.
vec4 samplePaged(sampler2DArray atlas, bool bySampler, uint indexBase, int levels, ivec2 size, TexelAddress address,
                 vec2 stepX, vec2 stepY, bool repeatX, int faceSide) {
  vec2 texels = vec2(size);
#ifdef STRATA_GEOMETRY_STAGE
  return samplePagedTexels(atlas, bySampler,
                           pagedLevels(indexBase, levels, max(length(stepX * texels), length(stepY * texels))), size,
                           repeatX ? wrappedAround(address, size.x) : address, -1);
#else
  return samplePagedAnisotropic(atlas, bySampler, indexBase, levels, size, address, stepX * texels, stepY * texels,
                                repeatX, faceSide);
#endif
}
