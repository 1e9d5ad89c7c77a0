#version 450 core
// The least visible height of a frame, for the next frame's primary reference sphere ([Mahsman 2010, §3.4.1],
// its second method; plugins/geometry-pgm/visible_radius.cpp). The input holds each pixel's height above the
// body's radius in metres, +infinity where no terrain was drawn. Each invocation folds a block of 4 x 4 texels,
// each 16 x 16 workgroup its invocations' in shared memory, then one atomicMin per workgroup folds them all into
// one uint: one dispatch, where the thesis's min mipmap takes a pass per level. The blocks keep the workgroups,
// and their barriers, few: llvmpipe runs each barrier of each workgroup as a switch of all its invocations, and
// a texel per invocation took most of the geometry's pass. GL 4.5 has no float atomicMin, so the heights go through
// orderedBits, which orders their uints as the floats are ordered; min is exact, so the result is the least
// texel to the bit, whatever order the workgroups finish in.
layout(local_size_x = 16, local_size_y = 16) in;

// m above the body's radius, +infinity uncovered: STRATA_HEIGHTS_SAMPLER is sampler2D, or sampler2DMS where the
// frame is multisampled, STRATA_HEIGHT_SAMPLES samples per pixel.
layout(binding = 0) uniform STRATA_HEIGHTS_SAMPLER heights;
const int kSamples = STRATA_HEIGHT_SAMPLES;
layout(std430, binding = 0) buffer Least { uint least; };  // orderedBits of the minimum; cleared to +inf's

uniform ivec2 size;  // the part of `heights` to reduce, from its corner (0, 0)

const int kBlock = 4;  // texels an invocation folds each way: visible_radius.cpp's dispatch counts them

const uint kGroupSize = 256u;
const float kUncovered = uintBitsToFloat(0x7f800000u);  // +infinity

shared float partial[kGroupSize];

// The least of a pixel's samples: every one of them shows terrain.
float leastOfPixel(ivec2 texel) {
  float least = texelFetch(heights, texel, 0).r;
  for (int i = 1; i < kSamples; ++i) least = min(least, texelFetch(heights, texel, i).r);
  return least;
}

// The least of the block of texels from `corner`, within `size`.
float leastOfBlock(ivec2 corner) {
  float least = kUncovered;
  for (int y = 0; y < kBlock; ++y)
    for (int x = 0; x < kBlock; ++x) {
      ivec2 texel = corner + ivec2(x, y);
      if (all(lessThan(texel, size))) least = min(least, leastOfPixel(texel));
    }
  return least;
}

// A uint that compares as the float does: positives get the sign bit set, negatives are flipped whole.
uint orderedBits(float value) {
  const uint bits = floatBitsToUint(value);
  return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

void main() {
  const uint index = gl_LocalInvocationIndex;
  partial[index] = leastOfBlock(ivec2(gl_GlobalInvocationID.xy) * kBlock);
  memoryBarrierShared();
  barrier();
  for (uint stride = kGroupSize / 2u; stride > 0u; stride /= 2u) {
    if (index < stride) partial[index] = min(partial[index], partial[index + stride]);
    memoryBarrierShared();
    barrier();
  }
  if (index == 0u) atomicMin(least, orderedBits(partial[0]));
}
