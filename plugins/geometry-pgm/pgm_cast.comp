#version 450 core
// The cast pass of projective grid mapping ([Mahsman 2010, §3.6]): each point of a W x H grid becomes a
// ray of the sampling camera, cast onto the reference spheres through the 2D cross section of
// plugins/geometry-pgm/cross_section.cpp, in float; tests/pgm/pgm_cast_test.cpp holds it to that double
// reference. A ray that misses the primary sphere is drawn where the ray of its cross-section plane that
// grazes the sphere meets it, on the horizon, so that the mesh reaches the horizon rather than stopping up to
// a grid row short of it (the thesis leaves misses unsaid; docs/references.md, Errata); with a secondary
// sphere that point lies beyond the horizon at gamma0, where the blend ends. The pass writes the sphere
// normal and the position from the eye, both in the east-north-up frame
// at the point below the eye (strata/camera.hpp's planetToLocal), where the nadir is exactly (0, 0, -1):
// a nadir rounded to float would shift the planet's centre sideways by d times its rounding.
//
// Precision ([Mahsman 2010, §3.6.5]): nothing planet-sized is subtracted here. 1 m above Mars a float
// holding the eye's distance from the centre resolves 0.25 m; the altitude is uploaded as such and as
// eps = a/r_p, the normal angle gamma is formed from eps in the cancellation-free form, and the position's
// components, a + 2 r_p sin^2(gamma/2) and r_p sin(gamma), are sums of positive terms that keep float's
// relative precision at every distance: a point 1 m below the eye is resolved to about 0.1 um (measured
// 1 m up: 0.4 um straight down, 2.6 um within 5 m of the eye tilted 85 degrees). The trig is
// strata/precise_trig.glsl's: NVIDIA's sin and cos are good to 4e-7 absolute only, wrong for angles of
// 1e-7 rad (1 m above the ground near the nadir), and llvmpipe's asin is bad for tiny arguments.
#include "strata/precise_trig.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) writeonly buffer Normals { vec4 normals[]; };  // xyz: s, local; w: 1 hit, 0 miss
layout(std430, binding = 1) writeonly buffer Positions { vec4 positions[]; };  // xyz: from the eye, m, local; w: as the normal's

uniform ivec2 gridSize;
uniform vec4 frustum;  // left, right, bottom, top on the near plane
uniform float near;
uniform mat3 samplingToLocal;     // the rotation from sampling space to the local frame
uniform float altitude;           // a = d - r_p, m
uniform float relativeAltitude;   // eps = a/r_p
uniform float primaryRadius;      // r_p, m
uniform float primaryTangent;     // tau0
uniform float horizonSine;        // sin(tau0) = r_p/d
uniform float horizonCosine;      // cos(tau0)
uniform float blendStart;         // b = zeta tau0
uniform bool hasSecondary;        // false beyond the distance where the secondary sphere vanishes
uniform float secondarySpan;      // tau_s - b
uniform float outermostAngle;     // gamma0 = pi/2 - tau_s
uniform float outermostTangent;   // tan(gamma0) = 1 / tan(tau_s)

// Below this sine of the ray angle the ray is the nadir: the point it gives lies within 1e-8 a of the
// nadir point, below the rounding of a itself.
const float kNadirSine = 1e-8;

// The grid's outer rows and columns lie on the frustum's edges, x/(W - 1) rather than (x + 0.5)/W: the
// sampling camera was fitted to rays on those edges (the nadir, the tangent planes of the visible-sphere
// frustum), and a mesh of the grid's points must reach them ([Mahsman 2010, §3.5.4]). In the local frame.
vec3 gridRay(ivec2 point) {
  vec2 along = vec2(point) / vec2(gridSize - 1);
  return normalize(samplingToLocal * vec3(mix(frustum.xz, frustum.yw, along), -near));
}

// delta = (c^2 - 1) u^2 with c = d/r_p = 1 + eps, so that Eq. 3.10 loses nothing where c is next to 1.
float shortfall(float sinRay) { return relativeAltitude * (2.0 + relativeAltitude) * sinRay * sinRay; }

// Beyond the primary tangent ([Mahsman 2010, §3.6.3]), or more than 90 degrees from the nadir.
bool misses(float sinRay, float cosRay) { return cosRay < 0.0 || cosRay * cosRay < shortfall(sinRay); }

// asin(c u) - asin(u) ([Mahsman 2010, §3.6.4, Eq. 3.10]) as asin(u [eps w + delta / (w + sqrt(w^2 - delta))]),
// which cancels nothing.
float frontNormalAngle(float sinRay, float cosRay) {
  float delta = shortfall(sinRay);
  float exitCosine = sqrt(max(cosRay * cosRay - delta, 0.0));
  return preciseAsin(sinRay * (relativeAltitude * cosRay + delta / (cosRay + exitCosine)));
}

// asin((d/r_s) sin(omega_s)) - omega_s ([Mahsman 2010, §3.6.4]) with omega_s = tau_s - g, g = (1 - f)(tau_s - b).
// As d/r_s = 1/sin(tau_s), the asin's argument is 1 - h with h = 2 sin^2(g/2) + sin(g)/tan(tau_s), and
// asin(1 - h) = pi/2 - 2 asin(sqrt(h/2)): no argument rounded next to 1, where asin's slope is infinite.
// h below 0 is the reference's argument clamped at 1.
float secondaryNormalAngle(float blend) {
  float g = (1.0 - blend) * secondarySpan, s, c;
  preciseSinCos(0.5 * g, s, c);
  float h = max(2.0 * s * (s + c * outermostTangent), 0.0);
  return outermostAngle + g - 2.0 * preciseAsin(sqrt(0.5 * h));
}

// mix(gamma_p, gamma_s, f) with the blend f = clamp((omega - b)/(tau0 - b), 0, 1), which Eq. 3.11 prints the
// other way round against its own text ([Mahsman 2010, §3.6.4, Eq. 3.11]; docs/references.md, Errata). With
// zeta = 1, b = tau0 and the blend is a step at the tangent: the span is kept above 0.
float normalAngle(float sinRay, float cosRay) {
  float primary = frontNormalAngle(sinRay, cosRay);
  float blend = clamp((preciseAtan(sinRay, cosRay) - blendStart) / max(primaryTangent - blendStart, 1e-30), 0.0, 1.0);
  if (blend == 0.0 || !hasSecondary) return primary;
  return primary + blend * (secondaryNormalAngle(blend) - primary);
}

void main() {
  ivec2 point = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(point, gridSize))) return;
  int i = point.y * gridSize.x + point.x;
  vec3 ray = gridRay(point);
  // The cross-section basis ([Mahsman 2010, §3.6.2]) with the nadir n = (0, 0, -1): sin(omega) = |n x ray| is
  // the ray's horizontal length, and k = (n x ray) x n / sin(omega) its horizontal direction.
  float sinRay = length(ray.xy), cosRay = -ray.z;
  bool hit = !misses(sinRay, cosRay);
  vec2 side = sinRay >= kNadirSine ? ray.xy / sinRay : vec2(1.0, 0.0);  // straight up: any plane will do
  if (!hit) {  // the ray of its plane that grazes the primary sphere: the mesh reaches the horizon
    sinRay = horizonSine;
    cosRay = horizonCosine;
  }
  float gamma = hit && sinRay < kNadirSine ? 0.0 : normalAngle(sinRay, cosRay);
  // s = -n cos(gamma) + k sin(gamma) ([Mahsman 2010, §3.6.4, Eq. 3.12]); the position r_p s - d n without d,
  // as the printed t = a sin(rho) / sin(chi) is just a ([Mahsman 2010, §3.6.5]; docs/references.md, Errata).
  float sinGamma, cosGamma, sinHalf, cosHalf;
  preciseSinCos(gamma, sinGamma, cosGamma);
  preciseSinCos(0.5 * gamma, sinHalf, cosHalf);
  float flag = hit ? 1.0 : 0.0;
  normals[i] = vec4(side * sinGamma, cosGamma, flag);
  positions[i] = vec4(primaryRadius * sinGamma * side, -(altitude + 2.0 * primaryRadius * sinHalf * sinHalf), flag);
}
