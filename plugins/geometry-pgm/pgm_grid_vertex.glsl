// A vertex of projective grid mapping's displaced grid, as pgm_displace.comp writes it and pgm_grid.vert
// reads it (plugins/geometry-pgm/grid_mesh.hpp's GridMesh::Vertex).
struct GridVertex {
  vec4 point;    // xyz: the displaced point, m from the eye, local frame; w: its height above the body's radius
  vec4 normal;   // xyz: s, the sphere normal, local frame; w: 1 for a hit, 0 on a missed ray's horizon
  vec4 shading;  // xyz: the displaced surface's normal, planet-fixed
};
