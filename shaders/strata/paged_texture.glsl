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

// The derivative along one axis at slot texel `at` from `behind` and `ahead` of it, one texel either side: central,
// or one-sided where `at` lies on the slot's edge (at 0 or kPagePayload + 1; a page's seam, one texel in 512).
vec4 slotDifference(vec4 behind, vec4 here, vec4 ahead, int at) {
  if (at <= 0) return ahead - here;
  if (at >= kPagePayload + 1) return here - behind;
  return 0.5 * (ahead - behind);
}

// The gradient along slot texel x and y at `f` within the cell whose first texel is `corner`, of texels t00 (at the
// corner), t10, t01 and t11: the central differences at the cell's four texels, mixed bilinearly, so that slopes vary
// continuously across cells (the bilinear interpolant's own gradient jumps at each texel, and is first order only).
TexelGradient slotGradient(sampler2DArray atlas, ivec2 corner, vec2 f, int slot, vec4 t00, vec4 t10, vec4 t01,
                           vec4 t11) {
  ivec2 before = max(corner - 1, 0), after = min(corner + 2, kPagePayload + 1);
  vec4 w0 = texelFetch(atlas, ivec3(before.x, corner.y, slot), 0);
  vec4 w1 = texelFetch(atlas, ivec3(before.x, corner.y + 1, slot), 0);
  vec4 e0 = texelFetch(atlas, ivec3(after.x, corner.y, slot), 0);
  vec4 e1 = texelFetch(atlas, ivec3(after.x, corner.y + 1, slot), 0);
  vec4 s0 = texelFetch(atlas, ivec3(corner.x, before.y, slot), 0);
  vec4 s1 = texelFetch(atlas, ivec3(corner.x + 1, before.y, slot), 0);
  vec4 n0 = texelFetch(atlas, ivec3(corner.x, after.y, slot), 0);
  vec4 n1 = texelFetch(atlas, ivec3(corner.x + 1, after.y, slot), 0);
  vec4 x00 = slotDifference(w0, t00, t10, corner.x), x10 = slotDifference(t00, t10, e0, corner.x + 1);
  vec4 x01 = slotDifference(w1, t01, t11, corner.x), x11 = slotDifference(t01, t11, e1, corner.x + 1);
  vec4 y00 = slotDifference(s0, t00, t01, corner.y), y01 = slotDifference(t00, t01, n0, corner.y + 1);
  vec4 y10 = slotDifference(s1, t10, t11, corner.y), y11 = slotDifference(t10, t11, n1, corner.y + 1);
  return TexelGradient(mix(mix(x00, x10, f.x), mix(x01, x11, f.x), f.y),
                       mix(mix(y00, y10, f.x), mix(y01, y11, f.x), f.y));
}

// Bilinear filtering within atlas slot `slot` at slot texel position `position` (texel centres at integers): the
// border makes the four texels always lie in the slot. `bySampler`: the sampler filters (a colour atlas, in a
// fragment stage), its 8-bit weights finer than colour shows, and `gradient` is 0; else by hand with texel
// fetches, as heights and values need: their differences shade relief, and llvmpipe gave one vertex different
// filtered values in different invocations (see surface_point.glsl). `gradient`: per slot texel (slotGradient;
// compilers drop it, and its fetches, where it is not read).
vec4 slotBilinear(sampler2DArray atlas, vec2 position, int slot, bool bySampler, out TexelGradient gradient) {
  gradient = TexelGradient(vec4(0.0), vec4(0.0));
#ifndef STRATA_GEOMETRY_STAGE
  if (bySampler) return textureLod(atlas, vec3((position + 0.5) / float(kPagePayload + 2), float(slot)), 0.0);
#endif
  ivec2 corner = clamp(ivec2(floor(position)), ivec2(0), ivec2(kPagePayload));
  vec2 f = clamp(position - vec2(corner), 0.0, 1.0);
  vec4 t00 = texelFetch(atlas, ivec3(corner, slot), 0);
  vec4 t10 = texelFetch(atlas, ivec3(corner.x + 1, corner.y, slot), 0);
  vec4 t01 = texelFetch(atlas, ivec3(corner.x, corner.y + 1, slot), 0);
  vec4 t11 = texelFetch(atlas, ivec3(corner + 1, slot), 0);
  gradient = slotGradient(atlas, corner, f, slot, t00, t10, t01, t11);
  return mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
}

// The value at level-0 texel `address` on pyramid level `level`, filtered bilinearly within one slot
// (slotBilinear), with its gradient per level-0 texel. Where the page is not loaded, the coarser page its index entry
// references is sampled instead; where nothing is, vec4(0). `face`: as pageRange.
vec4 samplePagedLevel(sampler2DArray atlas, bool bySampler, uint indexBase, ivec2 size, int level, TexelAddress address,
                      int face, out TexelGradient gradient) {
  gradient = TexelGradient(vec4(0.0), vec4(0.0));
  ivec2 levelSize = pagedLevelSize(size, level), low, high;
  pageRange(levelSize, face, low, high);
  vec2 part;
  ivec2 page = pageAt(levelTexel(address, level, part), low, high);
  uint entry = pageIndexEntry(pageIndexEntry(indexBase + uint(level)) +
                              uint(page.y * ((levelSize.x + kPagePayload - 1) / kPagePayload) + page.x));
  if (entry == 0u) return vec4(0.0);
  int held = int((entry >> 16) & 31u);
  ivec2 whole = levelTexel(address, held, part);
  pageRange(pagedLevelSize(size, held), face, low, high);
  page = pageAt(whole, low, high);
  // Slot texel positions, centres at integers: level texel j of the page is slot texel j + 1. The whole
  // texels' difference is exact, and small: the position is a float of a page's size.
  vec2 position = vec2(whole - page * kPagePayload) + part + 0.5;
  vec4 value = slotBilinear(atlas, position, int(entry & 0xffffu), bySampler, gradient);
  float perLevel0Texel = 1.0 / float(1 << held);
  gradient = TexelGradient(gradient.alongX * perLevel0Texel, gradient.alongY * perLevel0Texel);
  return value;
}

// Trilinear sampling across levels ([Kooima 2008, §4.3.2]: "a shader implementation of trilinear
// mipmapping") at level-0 texel `address`, the level chosen from the footprint: level-0 texels to the next
// sample; with its gradient, mixed alike. `face`: as pageRange.
vec4 samplePagedTexels(sampler2DArray atlas, bool bySampler, uint indexBase, int levels, ivec2 size,
                       TexelAddress address, float footprint, int face, out TexelGradient gradient) {
  float lod = clamp(log2(footprint), 0.0, float(levels - 1));
  int level = int(floor(lod));
  vec4 fine = samplePagedLevel(atlas, bySampler, indexBase, size, level, address, face, gradient);
  if (level + 1 >= levels || fract(lod) == 0.0) return fine;
  TexelGradient coarser;
  vec4 coarse = samplePagedLevel(atlas, bySampler, indexBase, size, level + 1, address, face, coarser);
  gradient = TexelGradient(mix(gradient.alongX, coarser.alongX, fract(lod)),
                           mix(gradient.alongY, coarser.alongY, fract(lod)));
  return mix(fine, coarse, fract(lod));
}

// `address` taken into the one period [0, width) of a raster around the body.
TexelAddress wrappedAround(TexelAddress address, int width) {
  float carried = floor(address.part.x);
  int x = address.whole.x + int(carried);
  if (x < 0) x += width * ((width - 1 - x) / width);  // % is defined for operands >= 0 only
  address.whole.x = x % width;
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
                            TexelAddress address, vec2 stepX, vec2 stepY, bool repeatX, int faceSide,
                            out TexelGradient gradient) {
  AnisotropicTaps taps = anisotropicTaps(stepX, stepY);
  int face = faceSide > 0 ? (address.whole.x + int(floor(address.part.x))) / faceSide : -1;
  vec4 sum = vec4(0.0);
  gradient = TexelGradient(vec4(0.0), vec4(0.0));
  int tap = 0;
  do {  // do-while: llvmpipe runs a loop's body once more, masked, when its test comes first
    TexelAddress at = address;
    at.part += tapOffset(taps, tap);
    if (repeatX) at = wrappedAround(at, size.x);
    if (face >= 0) at = clampedToFace(at, face, faceSide);
    TexelGradient tapGradient;
    sum += samplePagedTexels(atlas, bySampler, indexBase, levels, size, at, taps.width, face, tapGradient);
    gradient = TexelGradient(gradient.alongX + tapGradient.alongX, gradient.alongY + tapGradient.alongY);
  } while (++tap < taps.count);
  gradient = TexelGradient(gradient.alongX / float(taps.count), gradient.alongY / float(taps.count));
  return sum / float(taps.count);
}

// The same for a raster's own texels, the footprint given as texture coordinates' steps to the next sample;
// a raster around the body (`repeatX`) wraps the address into its one period. Fragment stages filter
// anisotropically (`faceSide`: as samplePagedAnisotropic's); geometry stages (heights for vertices)
// trilinearly at the longer step, their spacing. `bySampler` and `gradient`: as slotBilinear's, per level-0 texel.
vec4 samplePaged(sampler2DArray atlas, bool bySampler, uint indexBase, int levels, ivec2 size, TexelAddress address,
                 vec2 stepX, vec2 stepY, bool repeatX, int faceSide, out TexelGradient gradient) {
  vec2 texels = vec2(size);
#ifdef STRATA_GEOMETRY_STAGE
  return samplePagedTexels(atlas, bySampler, indexBase, levels, size,
                           repeatX ? wrappedAround(address, size.x) : address,
                           max(length(stepX * texels), length(stepY * texels)), -1, gradient);
#else
  return samplePagedAnisotropic(atlas, bySampler, indexBase, levels, size, address, stepX * texels, stepY * texels,
                                repeatX, faceSide, gradient);
#endif
}
