// composite.layer_peel's cutaway ([Kooima 2008, §1.1, ch. 6], layered data peeling, which asks for a way to
// select and peel away the upper layers: here, cutting them away). Distances are angles along the ground
// (rad), so the body's radius is not needed here.

// Where the upper layers are cut away (plugins/composite-layer-peel/cutaway.hpp).
struct Cutaway {
  int shape;     // 0 everywhere, 1 radius, 2 box, 3 plane
  vec3 centre;   // unit, planet-fixed: the radius's centre
  float radius;  // rad
  vec4 box;      // rad: west, south, east, north (east > west, past pi across the antimeridian)
  vec3 plane;    // unit normal of the vertical plane, towards the side cut away
  float edge;    // rad: the width of the wall's slope outside the region
};

// The distance along the ground (rad) from `p` into the region: positive inside, negative outside (for a
// box, from its nearest side). The radius's is the chord's angle, which float keeps to centimetres near the
// centre where acos would lose metres.
float cutawayDistance(SurfacePoint p, Cutaway c) {
  if (c.shape == 1) return c.radius - 2.0 * asin(min(0.5 * length(p.normal - c.centre), 1.0));
  if (c.shape == 2) {
    float middle = 0.5 * (c.box.x + c.box.z), offset = p.lonlat.x - middle;
    float lon = middle + offset - TWO_PI * round(offset / TWO_PI), across = cos(p.lonlat.y);
    return min(min(lon - c.box.x, c.box.z - lon) * across, min(p.lonlat.y - c.box.y, c.box.w - p.lonlat.y));
  }
  if (c.shape == 3) return asin(clamp(dot(p.normal, c.plane), -1.0, 1.0));
  return 1.0;
}

// How far the cut goes at `p`: 1 inside the region, falling to 0 across the edge outside it, or a step at
// its boundary without an edge.
float cutawayWeight(SurfacePoint p, Cutaway c) {
  float inside = cutawayDistance(p, c);
  return c.edge > 0.0 ? clamp(1.0 + inside / c.edge, 0.0, 1.0) : step(0.0, inside);
}
