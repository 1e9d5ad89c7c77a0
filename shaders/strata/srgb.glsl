// The sRGB transfer function (IEC 61966-2-1), from scene-linear to display-encoded values.
vec3 linearToSrgb(vec3 linear) {
  vec3 c = clamp(linear, 0.0, 1.0);
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
