// The light of a body's air along a ray: what the air scatters toward the eye, and the share of what lies
// behind that reaches it, for a sun of irradiance 1 (docs/atmosphere.md). Single scattering is integrated along
// the ray; the sun's transmittance and the light scattered twice and more come from tables computed once on the
// CPU in double (strata/atmosphere_tables.hpp) [Bruneton 2008, §4; Hillaire 2020, "Rendering the sky"]. The
// same sums in double, airLightAlong in core/foundation/src/air_light.cpp, judge these in the tests.
//
// Positions are planet-fixed metres in float: the air changes over kilometres (its scale heights), so the half
// metre float resolves at the body's radius moves nothing a pixel shows.
#include "strata/constants.glsl"

uniform sampler2D airTransmittance;       // AtmosphereTables::transmittance
uniform sampler2D airMultipleScattering;  // AtmosphereTables::multipleScattering
uniform vec2 airRadii;                    // m: the ground's (the body's radius) and the top of the air's
uniform vec3 airRayleigh;                 // 1/m: the molecules' scattering at the ground, per channel
uniform vec3 airMie;                      // the aerosols' scattering and extinction at the ground (1/m), and g
uniform vec2 airScaleHeights;             // m: the molecules' and the aerosols'

// Farther than 300 radii of the top of the air (the body 0.2 degrees across) float fails the ray's geometry: the
// discriminant b^2 - c errs by about 6e-8 (distance / radius)^2 of itself, half a per cent at 300 radii and growing
// as the square, and sample points lie 6e-8 of the distance astray (120 m for the Earth). The air is not drawn
// from there (docs/atmosphere.md).
const float kAirFarthest = 300.0;

const int kAirSteps = 32;  // segments along a ray: within 1.7 8-bit levels of 500 in double in the tests

struct AirLight {
  vec3 inscattered;    // radiance per unit of the sun's irradiance
  vec3 transmittance;  // of the path
};

// [Bruneton 2008, §2]: Rayleigh's phase function, and the aerosols' Cornette-Shanks one.
float airRayleighPhase(float nu) { return 3.0 / (16.0 * PI) * (1.0 + nu * nu); }
float airMiePhase(float nu, float g) {
  float g2 = g * g;
  return 3.0 / (8.0 * PI) * (1.0 - g2) * (1.0 + nu * nu) / ((2.0 + g2) * pow(1.0 + g2 - 2.0 * g * nu, 1.5));
}

// The square root of a^2 - b^2, as (a - b)(a + b): float keeps its digits where a is near b.
float airRootOfDifference(float a, float b) { return sqrt(max((a - b) * (a + b), 0.0)); }

// Whether the ray from radius r at zenith cosine mu meets the ground.
bool airMeetsGround(float r, float mu) {
  return mu < 0.0 && (airRadii.x - r) * (airRadii.x + r) + r * r * mu * mu >= 0.0;
}

// A table's texture coordinates of (x, y) in [0, 1]^2, its points lying at the texel centres.
vec2 airTableCoordinates(sampler2D table, vec2 unit) {
  vec2 size = vec2(textureSize(table, 0));
  return 0.5 / size + clamp(unit, 0.0, 1.0) * (1.0 - 1.0 / size);
}

// The transmittance to the top of the air along (r, mu); 0 where the ray meets the ground [Bruneton 2008, §4], in
// the coordinates of transmittanceCoordinates (core/foundation/src/atmosphere_tables.cpp).
vec3 airTransmittanceToTop(float r, float mu) {
  if (airMeetsGround(r, mu)) return vec3(0.0);
  float horizon = airRootOfDifference(airRadii.y, airRadii.x), rho = airRootOfDifference(r, airRadii.x);
  float least = airRadii.y - r, most = rho + horizon;
  float d = max(-r * mu + sqrt(max((airRadii.y - r) * (airRadii.y + r) + r * r * mu * mu, 0.0)), 0.0);
  vec2 unit = vec2(most > least ? (d - least) / (most - least) : 0.0, rho / horizon);
  return texture(airTransmittance, airTableCoordinates(airTransmittance, unit)).rgb;
}

// Psi_ms at radius r under a sun of zenith cosine muSun [Hillaire 2020, "Multiple scattering LUT"].
vec3 airMultipleScatteringAt(float r, float muSun) {
  vec2 unit = vec2(0.5 * muSun + 0.5, (r - airRadii.x) / (airRadii.y - airRadii.x));
  return texture(airMultipleScattering, airTableCoordinates(airMultipleScattering, unit)).rgb;
}

// The share of the sun's light that reaches the ground of sphere normal `up` through the air: reddened toward the
// horizon. Below the horizon, the horizon's: the twilight fades what is left (composite.frag's daylight).
vec3 airSunlightOnGround(vec3 up, vec3 sun) { return airTransmittanceToTop(airRadii.x, max(dot(up, sun), 0.0)); }

// Where the ray from `origin` along the unit `direction` lies within the sphere of `radius` about the centre:
// its distances in (x) and out (y); false where it misses the sphere or it lies behind.
bool airWithinSphere(vec3 origin, vec3 direction, float radius, out vec2 span) {
  float b = dot(origin, direction);
  float c = (length(origin) - radius) * (length(origin) + radius);
  float discriminant = b * b - c;
  span = vec2(-b) + vec2(-1.0, 1.0) * sqrt(max(discriminant, 0.0));
  return discriminant >= 0.0 && span.y > 0.0;
}

// (1 - T) / extinction per channel, T the segment's transmittance: the light scattered within a segment `segment`
// m long, dimmed within it as well [Hillaire 2020, "Rendering the sky"].
vec3 airScatteredOverSegment(vec3 extinction, vec3 transmittance, float segment) {
  return mix((1.0 - transmittance) / max(extinction, vec3(1e-30)), vec3(segment),
             lessThan(extinction * segment, vec3(1e-6)));
}

// The span of segment `i` of the march from `start` to `end` (m along the ray): the segments narrow quadratically
// toward `lowest`, where the ray passes nearest the ground and the air is densest, each side of it taking a share
// of them by its length. Even segments missed the haze: looking 17 degrees up from the ground, the first of 32
// spans the aerosols' 1.2 km scale height, and the sky near the sun came out 4 levels dark.
vec2 airSegment(int i, float start, float lowest, float end) {
  int before = int(round(float(kAirSteps) * (lowest - start) / (end - start)));
  bool near = i < before;
  float count = float(near ? before : kAirSteps - before), k = float(near ? i : i - before);
  vec2 u = vec2(k, k + 1.0) / count;
  return near ? lowest - (lowest - start) * (1.0 - u) * (1.0 - u) : lowest + (end - lowest) * u * u;
}

// The air's light along the first `reach` m of the ray from `origin` along the unit `direction`, lit by a sun
// in the unit direction `sun`, up to where the ray leaves the air or meets the ground.
AirLight airLightAlong(vec3 origin, vec3 direction, float reach, vec3 sun) {
  AirLight light = AirLight(vec3(0.0), vec3(1.0));
  vec2 air, ground;
  if (length(origin) > kAirFarthest * airRadii.y || !airWithinSphere(origin, direction, airRadii.y, air)) return light;
  if (airWithinSphere(origin, direction, airRadii.x, ground) && ground.x > 0.0) air.y = min(air.y, ground.x);
  float start = max(air.x, 0.0), end = min(air.y, reach);
  if (end <= start) return light;
  float nu = dot(direction, sun), lowest = clamp(-dot(origin, direction), start, end);
  float rayleigh = airRayleighPhase(nu), mie = airMiePhase(nu, airMie.z);
  for (int i = 0; i < kAirSteps; ++i) {
    vec2 span = airSegment(i, start, lowest, end);
    float step = span.y - span.x;
    vec3 point = origin + 0.5 * (span.x + span.y) * direction;
    float r = length(point), muSun = dot(point, sun) / r;
    float altitude = r - airRadii.x;
    vec3 molecules = airRayleigh * exp(-altitude / airScaleHeights.x);
    float aerosolDensity = exp(-altitude / airScaleHeights.y), aerosols = airMie.x * aerosolDensity;
    vec3 source = (molecules * rayleigh + aerosols * mie) * airTransmittanceToTop(r, muSun) +
                  (molecules + aerosols) * airMultipleScatteringAt(r, muSun);
    vec3 extinction = molecules + airMie.y * aerosolDensity, segment = exp(-extinction * step);
    light.inscattered += light.transmittance * source * airScatteredOverSegment(extinction, segment, step);
    light.transmittance *= segment;
  }
  return light;
}
