// composite.relief's pieces: shaded relief (seed 000 section 1.1; digest 000 section 6).

// The sample's footprint along the ground, rad: the longer of its two steps (SurfacePoint), so that the
// height's differences span a pixel.
float reliefStep(SurfacePoint p) {
  float c = cos(p.lonlat.y);
  return max(max(length(vec2(p.lonlatDx.x * c, p.lonlatDx.y)), length(vec2(p.lonlatDy.x * c, p.lonlatDy.y))), 1e-12);
}

// The point `step` (rad of longitude, latitude) from `p`, with the same footprint. Its normal is turned
// from p's along the local east and north rather than rebuilt from lonlat, which float resolves to about a
// metre on Earth.
SurfacePoint reliefNeighbour(SurfacePoint p, vec2 step) {
  vec3 east = vec3(-sin(p.lonlat.x), cos(p.lonlat.x), 0.0);
  vec3 north = cross(p.normal, east);
  p.normal = normalize(p.normal + east * (step.x * cos(p.lonlat.y)) + north * step.y);
  p.lonlat += step;
  p.fromReference += step;
  return p;
}

// The rise of the height over one step, from the samples one step ahead and behind (.r, coverage in .a) and
// `h` between: central where both have data, one-sided where one has, flat where neither has.
float reliefDifference(vec4 ahead, float h, vec4 behind) {
  if (ahead.a > 0.0 && behind.a > 0.0) return 0.5 * (ahead.r - behind.r);
  if (ahead.a > 0.0) return ahead.r - h;
  return behind.a > 0.0 ? h - behind.r : 0.0;
}

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

// The slope of the heights times `exaggeration`, as a share of a right angle (0 flat, 1 vertical).
float reliefSlope(vec2 slopes, float exaggeration) { return atan(exaggeration * length(slopes)) / (0.5 * PI); }

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
