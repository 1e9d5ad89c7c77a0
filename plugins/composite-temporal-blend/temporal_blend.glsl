// composite.temporal_blend's mix ([Kooima 2008, §1.1, ch. 6], time-varying data).

// The two steps that bracket the date, mixed linearly in time: `fraction` 0 at the earlier step's date, 1 at
// the later's. Each counts by its coverage as well, so that where one step has no data the other shows,
// fading in or out with the date rather than darkening towards an empty value.
vec4 temporalBlend(vec4 earlier, vec4 later, float fraction) {
  float fromEarlier = earlier.a * (1.0 - fraction), fromLater = later.a * fraction, coverage = fromEarlier + fromLater;
  return coverage > 0.0 ? vec4((earlier.rgb * fromEarlier + later.rgb * fromLater) / coverage, coverage) : vec4(0.0);
}
