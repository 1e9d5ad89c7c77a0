// A point of a body's surface as layers sample it: where it is, and the footprint of the sample (how far
// longitude and latitude move to the next pixel or vertex), so each layer picks its own level of detail.
struct SurfacePoint {
  vec2 lonlat;    // rad; longitude is not wrapped and may lie outside [-pi, pi]
  vec3 normal;    // planet-fixed unit normal of the undisplaced sphere (+z north, +x at longitude 0)
  vec2 lonlatDx;  // change of lonlat to the next sample along x (longitude wrap already removed)
  vec2 lonlatDy;  // the same along y
};

// Samples `image` at `uv` over a footprint given as texture-coordinate steps along x and y. Fragment
// stages filter anisotropically (textureGrad). Vertex stages (heights for geometry) pick the level of
// the longer step and filter trilinearly: Mesa's llvmpipe returned non-finite values from textureGrad in
// vertex shaders, which tore holes in the displaced surface.
vec4 sampleFootprint(sampler2D image, vec2 uv, vec2 stepX, vec2 stepY) {
#ifdef STRATA_VERTEX_STAGE
  vec2 size = vec2(textureSize(image, 0));
  float longest = max(length(stepX * size), length(stepY * size));
  return textureLod(image, uv, max(log2(longest), 0.0));
#else
  return textureGrad(image, uv, stepX, stepY);
#endif
}
