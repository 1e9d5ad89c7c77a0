// The procedural planet of plugins/source-procedural/planet_model.cpp, in float: the same octaves, shifts,
// seeds, footprint limit and colour ramp (that file says why each is what it is).
#include "source-procedural/simplex_noise.glsl"
#include "strata/local_offsets.glsl"
#include "strata/surface_point.glsl"

struct ProceduralPlanet {
  int seed;
  float amplitude;        // m
  float wavelength;       // m, of the first octave
  int octaves;
  float contourInterval;  // m
  float radius;           // m, of the body
};

const float PLANET_GAIN = 0.5;
const vec3 PLANET_OCTAVE_SHIFT = vec3(0.6180339887, 0.3819660113, 0.2360679775);
const vec3 PLANET_CONTOUR_COLOUR = vec3(0.004);
const float PLANET_CONTOUR_HALF_WIDTH = 0.08;

// Metres of ground between this sample and the next, the longer of the footprint's two steps.
float planetFootprint(SurfacePoint p, float radius) {
  float cosLat = cos(p.lonlat.y);
  return radius * max(length(vec2(p.lonlatDx.x * cosLat, p.lonlatDx.y)),
                      length(vec2(p.lonlatDy.x * cosLat, p.lonlatDy.y)));
}

float planetOctaveWeight(int octave, float wavelength, float footprint) {
  if (octave == 0 || footprint <= 0.0) return 1.0;
  return clamp(log2(wavelength * exp2(-float(octave)) / (2.0 * footprint)), 0.0, 1.0);
}

// The planet's noise lattice about the frame's reference (plugins/source-procedural/planet_lattice.hpp):
// octave k's noise point of the reference's normal as anchor[k] (an integer skewed cell) plus local[k], for
// the first `octaves` octaves (0 where the reference is not known), and the reference's east, north and up.
const int PLANET_MAX_OCTAVES = 24;
struct PlanetLattice {
  ivec3 anchor[PLANET_MAX_OCTAVES];
  vec3 local[PLANET_MAX_OCTAVES];
  int octaves;
  mat3 frame;     // columns: east, north, up of the reference, planet-fixed
  vec2 latitude;  // sin and cos of the reference's
};

// A point's normal less the reference's, from its offsets to the reference: exact to float's relative
// precision however small, through the tangent plane (strata/local_offsets.glsl); the up component's drop
// 1 - sqrt(1 - r^2) written as r^2 / (1 + sqrt(1 - r^2)).
vec3 normalFromReference(vec2 fromReference, PlanetLattice lattice) {
  vec2 en = tangentOffset(fromReference, lattice.latitude);
  float r2 = dot(en, en);
  return lattice.frame * vec3(en, -r2 / (1.0 + sqrt(max(0.0, 1.0 - r2))));
}

// planetHeight at a surface point, each octave that has an anchor sampled from it plus the point's own small
// offset (2^k R / wavelength times its normal's offset from the reference's), the others as planetHeight
// samples them. The same heights where float resolves both; near the reference to micrometres.
float planetHeightAt(SurfacePoint p, float footprint, ProceduralPlanet planet, PlanetLattice lattice) {
  float scale = planet.radius / planet.wavelength;
  vec3 delta = normalFromReference(p.fromReference, lattice) * scale, point = p.normal * scale;
  float sum = 0.0, amplitude = 1.0;
  for (int k = 0; k < planet.octaves; ++k, amplitude *= PLANET_GAIN) {
    float weight = planetOctaveWeight(k, planet.wavelength, footprint);
    if (weight == 0.0) break;
    uint seed = uint(planet.seed) * 32u + uint(k);
    float noise = k < lattice.octaves ? simplexNoiseFrom(lattice.anchor[k], lattice.local[k] + exp2(float(k)) * delta, seed)
                                      : simplexNoise(exp2(float(k)) * point + float(k) * PLANET_OCTAVE_SHIFT, seed);
    sum += weight * amplitude * noise;
  }
  float total = (1.0 - pow(PLANET_GAIN, float(planet.octaves))) / (1.0 - PLANET_GAIN);
  return planet.amplitude * sum / total;
}

vec3 planetColour(float height, ProceduralPlanet planet) {
  float interval = planet.contourInterval;
  if (abs(height - interval * floor(height / interval + 0.5)) < PLANET_CONTOUR_HALF_WIDTH * interval)
    return PLANET_CONTOUR_COLOUR;
  float h = height / planet.amplitude;
  if (h < 0.0) return mix(vec3(0.004, 0.015, 0.08), vec3(0.03, 0.18, 0.42), clamp(h / 0.5 + 1.0, 0.0, 1.0));
  if (h < 0.2) return mix(vec3(0.05, 0.20, 0.03), vec3(0.38, 0.24, 0.07), h / 0.2);
  if (h < 0.4) return mix(vec3(0.38, 0.24, 0.07), vec3(0.22, 0.18, 0.15), (h - 0.2) / 0.2);
  if (h < 0.5) return mix(vec3(0.22, 0.18, 0.15), vec3(0.85, 0.87, 0.90), (h - 0.4) / 0.1);
  return vec3(0.85, 0.87, 0.90);
}
