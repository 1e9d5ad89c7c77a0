#version 450 core
#define STRATA_GEOMETRY_STAGE
STRATA_PROGRAM_DEFINES
// geometry.clipmap's static hemisphere (hemisphere_rings.hpp) turned to the viewer and displaced by the height
// layer ([Clasen & Hege 2006, §3.3, §3.4]). The paper turns each vertex by the viewer's colatitude (Eq. 3, whose sign
// the digest corrects) and takes its longitude and latitude by atan2 and acos (Eq. 4), which loses the small
// rings near the viewer to cancellation (the paper's Fig. 13; its Eqs. 9 to 14 approximate around it, §5.1).
// lonlatFromReference does that turn and both angles without cancellation, so every ring, down to a millimetre
// from the nadir, takes its longitude and latitude from the frame's reference exactly as float resolves them.
// Heights come from the height clipmaps (clipmap_heights.glsl). The vertex's place comes from the eye in the same
// frame, whose vertical difference the mesh holds as cos(theta~) - 1 (docs/architecture.md, "Precision").
#include "strata/constants.glsl"
#include "strata/precise_trig.glsl"
#include "strata/surface_point.glsl"
#include "strata/lonlat_from_reference.glsl"

layout(location = 0) in vec4 hemisphere;  // east, north, cos(theta~) - 1; theta~, negative on the western half

uniform mat3 localToEye;         // the east-north-up frame at View::reference to eye axes
uniform mat3 localToPlanet;      // the same frame to planet-fixed axes
uniform mat4 projection;
uniform vec2 referenceLatitude;  // sin and cos of the reference latitude
uniform vec2 referenceLonlat;    // rad: the point below the eye
uniform float radius;            // m
uniform float altitude;          // m: the eye above the radius

out vec2 vLonlatFromReference;
out vec3 vShadingNormal;

#ifdef STRATA_HAS_HEIGHT
#include "geometry-clipmap/clipmap_heights.glsl"
#include "strata/normal_of_slopes.glsl"
#endif

void main() {
  vec3 local = vec3(hemisphere.xy, 1.0 + hemisphere.z);
  vec2 lonlat = lonlatFromReference(local, referenceLatitude);
  vec3 normal = localToPlanet * local;
  vec3 shading = normal;
  float h = 0.0;
#ifdef STRATA_HAS_HEIGHT
  vec3 sampled = clipmapHeight(lonlat, abs(hemisphere.w));
  h = sampled.x;
  shading = normalOfSlopes(h, referenceLonlat + lonlat, normal, sampled.yz);
#endif
  vec3 fromEye = vec3((radius + h) * hemisphere.xy, (radius + h) * hemisphere.z + (h - altitude));
  gl_Position = projection * vec4(localToEye * fromEye, 1.0);
  // Unwrapped into the vertex's half of the mesh, east of the reference or west of it, so that no triangle
  // interpolates across the meridian beyond a pole, where the longitude from the reference jumps by a turn
  // ([Clasen & Hege 2006, §4.4]). After the heights, which the two copies of a seam's vertex sample alike.
  float side = hemisphere.w < 0.0 ? -0.5 * PI : 0.5 * PI;
  vLonlatFromReference = lonlat + vec2(TWO_PI * round((side - lonlat.x) / TWO_PI), 0.0);
  vShadingNormal = shading;
}
