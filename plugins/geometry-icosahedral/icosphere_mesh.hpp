#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace strata::icosahedral {

// One vertex as the GPU reads it. Offsets are relative to the vertex's patch centre so that floats only
// span a patch; the centre itself stays in double (DESIGN.md, Precision).
struct MeshVertex {
  glm::vec3 offsetFromCentre;  // planet-fixed, m
  glm::vec3 sphereNormal;      // planet-fixed unit normal
  glm::vec2 lonlat;            // rad; longitude unwrapped around the patch centre's
};

// The icosahedron split uniformly into 20 x 4^level patches, each subdivided `depth` times
// (nv(depth) = (2^depth + 1)(2^depth + 2) / 2 vertices per patch, seed 000 section 3.3.1). Patches
// follow one another in `vertices`; `indices` cover all patches with counter-clockwise triangles seen
// from outside.
struct IcosphereMesh {
  std::vector<glm::dvec3> patchCentres;  // planet-fixed, m, on the sphere
  std::vector<MeshVertex> vertices;
  std::vector<std::uint32_t> indices;
  int verticesPerPatch = 0;
  double vertexSpacing = 0.0;  // rad between neighbouring vertices, along the base icosahedron's edges
};

IcosphereMesh buildIcosphereMesh(double radius, int level, int depth);

}  // namespace strata::icosahedral
