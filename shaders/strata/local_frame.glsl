// The ground's local frame at longitude `lon` (rad) where the up is `up` (planet-fixed, unit: the sphere's
// normal, or a shading normal): east along the parallel, made perpendicular to up; north = up x east. Columns
// east, north, up: frame * v turns a vector from east/north/up into planet-fixed axes, v * frame back.
mat3 eastNorthUp(float lon, vec3 up) {
  vec3 east = vec3(-sin(lon), cos(lon), 0.0);
  east = normalize(east - up * dot(up, east));
  return mat3(east, cross(up, east), up);
}
