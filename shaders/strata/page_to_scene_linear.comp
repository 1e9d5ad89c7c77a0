#version 450 core
// Converts one colour page, in its atlas slot, from the colour space its source encodes it in to scene-linear
// (docs/colour.md), right after its upload, so that filtering between its texels mixes linear light. The
// texels hold encoded r, g, b premultiplied by coverage, then coverage: the conversion applies to the colour,
// so it is divided out first and multiplied back after.
layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0, rgba16f) uniform image2DArray atlas;
uniform int slot;

// vec4 strata_toSceneLinear(vec4): OpenColorIO's code for the source's colour space (PageSource).
STRATA_TO_SCENE_LINEAR_GLSL

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID.xy, slot);
  if (any(greaterThanEqual(texel.xy, imageSize(atlas).xy))) return;
  vec4 stored = imageLoad(atlas, texel);
  if (stored.a <= 0.0) return;
  vec3 linear = strata_toSceneLinear(vec4(stored.rgb / stored.a, 1.0)).rgb;
  imageStore(atlas, texel, vec4(linear * stored.a, stored.a));
}
