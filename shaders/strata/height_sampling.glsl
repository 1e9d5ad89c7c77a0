// Heights for the geometry generators' compute passes (geometry.icosahedral, geometry.pgm): the height layer
// sampled at a point given from the reference, and the displaced surface's shading normal. The including
// program defines STRATA_GEOMETRY_STAGE and STRATA_HEIGHT_FUNCTION (and STRATA_HEIGHT_FACE_FUNCTION where the
// layer's texels are HEALPix faces, STRATA_HEIGHT_SLOPED_FUNCTION where it gives its slopes), pastes the layer's GLSL before this
// file (strata/plugin/height_input.hpp gives both) and declares the uniforms
//   vec2 referenceLonlat  rad: the point below the eye (View::reference)
//   float radius          m: the body's, to turn height differences into slopes

// The surface point at `fromReference` (rad from the point below the eye) with a footprint of one vertex spacing
// along the ground each way: east, that is spacing / cos(latitude) of longitude. The footprint is the geometry's
// explicit stand-in for screen derivatives ([Kooima 2008, §4.1.2]), so a longitude/latitude map's texels near a
// pole show as the slivers they are to composite.projection_quality's isotropy weight, and each layer filters
// over the ground a vertex spans.
SurfacePoint vertexPoint(vec2 fromReference, vec3 normal, float spacing) {
  float east = spacing / max(cos(referenceLonlat.y + fromReference.y), 1e-4);
  return SurfacePoint(referenceLonlat + fromReference, normal, vec2(east, 0.0), vec2(0.0, spacing), fromReference);
}

// The height at `fromReference`, filtered over vertexPoint's footprint.
float heightAt(vec2 fromReference, vec3 normal, float spacing) {
  vec4 sampled = STRATA_HEIGHT_FUNCTION(vertexPoint(fromReference, normal, spacing));
  return sampled.a > 0.0 ? sampled.r : 0.0;  // no height data: the sphere
}

#ifdef STRATA_HEIGHT_FACE_FUNCTION
// The height at a HEALPix face point (face, x, y) of a layer whose texels are the faces
// (Layer::faceSamplingFunction), over a footprint of `spacing` rad: a face is sqrt(pi / 3) rad across, on
// average.
float heightAtFacePoint(vec3 point, float spacing) {
  vec4 sampled = STRATA_HEIGHT_FACE_FUNCTION(point, spacing / sqrt(PI / 3.0));
  return sampled.a > 0.0 ? sampled.r : 0.0;  // no height data: the sphere
}
#endif

#include "strata/normal_of_slopes.glsl"

#ifdef STRATA_HEIGHT_SLOPED_FUNCTION
// The height and its slopes (per rad along the ground) at `fromReference`, filtered as heightAt filters: one sample
// of a layer that gives its slopes with its value (SlopedLayer), its slopes over the vertex spacing's level.
vec4 slopedHeightAt(vec2 fromReference, vec3 normal, float spacing) {
  vec4 sampled = STRATA_HEIGHT_SLOPED_FUNCTION(vertexPoint(fromReference, normal, spacing));
  return sampled.a > 0.0 ? sampled : vec4(0.0);  // no height data: the sphere
}
#endif

// The displaced surface's normal at height `h`: from the layer's own slopes where it gives them, else from central
// differences of the height over one vertex spacing.
vec3 shadingNormal(float h, vec2 fromReference, vec3 normal, float spacing) {
  vec2 lonlat = referenceLonlat + fromReference;
#ifdef STRATA_HEIGHT_SLOPED_FUNCTION
  return normalOfSlopes(h, lonlat, normal, slopedHeightAt(fromReference, normal, spacing).gb);
#else
  float dLon = spacing / max(cos(lonlat.y), 1e-4);
  float eastRise = heightAt(fromReference + vec2(dLon, 0.0), normal, spacing) -
                   heightAt(fromReference - vec2(dLon, 0.0), normal, spacing);
  float northRise = heightAt(fromReference + vec2(0.0, spacing), normal, spacing) -
                    heightAt(fromReference - vec2(0.0, spacing), normal, spacing);
  return normalOfSlopes(h, lonlat, normal, vec2(eastRise, northRise) / (2.0 * spacing));
#endif
}

// The height at `fromReference` as heightAt has it, and in `shading` the displaced surface's normal there: one
// sample where the layer gives its slopes with its value, else five.
float heightAndShadingNormal(vec2 fromReference, vec3 normal, float spacing, out vec3 shading) {
#ifdef STRATA_HEIGHT_SLOPED_FUNCTION
  vec4 sampled = slopedHeightAt(fromReference, normal, spacing);
  shading = normalOfSlopes(sampled.r, referenceLonlat + fromReference, normal, sampled.gb);
  return sampled.r;
#else
  float h = heightAt(fromReference, normal, spacing);
  shading = shadingNormal(h, fromReference, normal, spacing);
  return h;
#endif
}
