// composite.relief's pieces: shaded relief ([Kooima 2008, §1.1]), of the slopes
// strata/height_slopes.glsl finds.

// Lambert's cosine law: the cosine of the angle between the surface normal, from the slopes east and north
// times the exaggeration, and `light` (unit, east/north/up), 0 facing away.
float reliefLambert(vec2 slopes, float exaggeration, vec3 light) {
  vec3 normal = normalize(vec3(-exaggeration * slopes, 1.0));
  return max(dot(normal, light), 0.0);
}

// `direction` (planet-fixed, unit) in the east/north/up frame of the ground at `p`: the sun as it stands
// over that point's horizon.
#include "strata/local_frame.glsl"

vec3 reliefLocalDirection(SurfacePoint p, vec3 direction) { return direction * eastNorthUp(p.lonlat.x, p.normal); }

// The sines and cosines of the azimuths of multidirectional, oblique-weighted shading's four lights (Mark 1992,
// USGS Open-File Report 92-422): 225, 270, 315 and 360 degrees clockwise from north.
const vec2 kObliqueAzimuths[4] = vec2[](vec2(-0.70710678, -0.70710678), vec2(-1.0, 0.0), vec2(-0.70710678, 0.70710678),
                                        vec2(0.0, 1.0));

// The shade under `light` (unit, east/north/up), or with `multidirectional` Mark's four lights at `altitude` (rad),
// each weighted by sin^2(aspect - azimuth) and halved (the weights sum to 2), so that a slope is lit most by the
// lights oblique to it and relief facing any way shows. The aspect, the compass direction the ground faces
// (downslope; north on flat ground), enters by its sine and cosine, which the slopes give without an angle. A
// do-while of one round or four, not a branch: llvmpipe runs both sides of a branch, masked.
float reliefShade(vec2 slopes, float exaggeration, vec3 light, bool multidirectional, float altitude) {
  float steepness = length(slopes);
  vec2 downslope = steepness > 0.0 ? -slopes / steepness : vec2(0.0, 1.0);  // (sin, cos) of the aspect
  vec3 oblique = vec3(cos(altitude), cos(altitude), sin(altitude));
  int lights = multidirectional ? 4 : 1;
  float sum = 0.0;
  int i = 0;
  do {
    vec2 azimuth = kObliqueAzimuths[i];
    float across = downslope.x * azimuth.y - downslope.y * azimuth.x;  // sin(aspect - azimuth)
    vec3 towards = multidirectional ? vec3(azimuth, 1.0) * oblique : light;
    sum += (multidirectional ? 0.5 * across * across : 1.0) * reliefLambert(slopes, exaggeration, towards);
  } while (++i < lights);
  return sum;
}

// The slope's angle (`aspect` false) as a share of a right angle, or the aspect as a share of a turn (0 on flat
// ground), from one arctangent.
float reliefAngle(vec2 slopes, float exaggeration, bool aspect) {
  float angle = atan(aspect ? -slopes.x : exaggeration * length(slopes), aspect ? -slopes.y : 1.0);
  if (!aspect) return angle / (0.5 * PI);
  return dot(slopes, slopes) > 0.0 ? mod(angle, TWO_PI) / TWO_PI : 0.0;
}

// A colour ramp's colour at `x`: linear in scene-linear light between its `count` stops (x in .x, rising;
// colour in .yzw), held beyond its first and last; white with none (no tint), for which the loop takes no round.
const int RELIEF_RAMP_STOPS = 8;
vec3 reliefRamp(vec4 stops[RELIEF_RAMP_STOPS], int count, float x) {
  if (count == 0) return vec3(1.0);
  if (x <= stops[0].x) return stops[0].yzw;
  for (int i = 1; i < count; ++i)
    if (x < stops[i].x)
      return mix(stops[i - 1].yzw, stops[i].yzw, (x - stops[i - 1].x) / (stops[i].x - stops[i - 1].x));
  return stops[max(count - 1, 0)].yzw;
}