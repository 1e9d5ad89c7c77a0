// composite.relief's pieces: shaded relief ([Kooima 2008, §1.1]), of the slopes
// strata/height_slopes.glsl finds.

// Lambert's cosine law: the cosine of the angle between the surface normal, from the slopes east and north
// times the exaggeration, and `light` (unit, east/north/up), 0 facing away.
float reliefLambert(vec2 slopes, float exaggeration, vec3 light) {
  vec3 normal = normalize(vec3(-exaggeration * slopes, 1.0));
  return max(dot(normal, light), 0.0);
}

// The unit vector towards a light at `azimuth` (rad clockwise from north) and `altitude` (rad above the
// horizon), in east/north/up.
vec3 reliefLight(float azimuth, float altitude) {
  return vec3(sin(azimuth) * cos(altitude), cos(azimuth) * cos(altitude), sin(altitude));
}

// The aspect, the compass direction the ground faces (downslope), rad clockwise from north in [0, 2 pi); 0
// on flat ground.
float reliefAspect(vec2 slopes) {
  return dot(slopes, slopes) > 0.0 ? mod(atan(-slopes.x, -slopes.y), TWO_PI) : 0.0;
}

// Multidirectional, oblique-weighted shading (Mark 1992, USGS Open-File Report 92-422): lights at azimuths
// 225, 270, 315 and 360 degrees, each weighted by sin^2(aspect - azimuth), so that a slope is lit most by the
// lights oblique to it and relief facing any way shows; the weights sum to 2.
float reliefMultidirectional(vec2 slopes, float exaggeration, float altitude) {
  float aspect = reliefAspect(slopes), sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    float azimuth = radians(225.0 + 45.0 * float(i)), oblique = sin(aspect - azimuth);
    sum += oblique * oblique * reliefLambert(slopes, exaggeration, reliefLight(azimuth, altitude));
  }
  return 0.5 * sum;
}

// A colour ramp's colour at `x`: linear in scene-linear light between its `count` stops (x in .x, rising;
// colour in .yzw), held beyond its first and last.
const int RELIEF_RAMP_STOPS = 8;
vec3 reliefRamp(vec4 stops[RELIEF_RAMP_STOPS], int count, float x) {
  if (x <= stops[0].x) return stops[0].yzw;
  for (int i = 1; i < count; ++i)
    if (x < stops[i].x) return mix(stops[i - 1].yzw, stops[i].yzw, (x - stops[i - 1].x) / (stops[i].x - stops[i - 1].x));
  return stops[count - 1].yzw;
}
