#include "gpu_patches.hpp"

#include <strata/gl/shader_library.hpp>

#include "rendering.hpp"

namespace strata::icosahedral::test {

GpuPatches::GpuPatches(const std::string& heightFunction, const std::string& heightGlsl)
    : context_(strata::test::headlessContext()), table_(kDepth), windings_(table_), buffers_(table_, windings_) {
  const std::string defines =
      heightFunction.empty() ? "" : "#define STRATA_HAS_HEIGHT\n#define STRATA_HEIGHT_FUNCTION " + heightFunction;
  program_ = ShaderProgram({{GL_COMPUTE_SHADER, "subdivide_patches.comp",
                             strata::test::pluginShaderLibrary().expand(
                                 "geometry-icosahedral/subdivide_patches.comp",
                                 {{"STRATA_PROGRAM_DEFINES", defines}, {"STRATA_HEIGHT_LAYER_GLSL", heightGlsl}})}});
}

GpuPatches::Subdivided GpuPatches::subdivide(const std::vector<Patch>& patches, const View& view,
                                             double splitDistanceUnit, bool onTerrain) {
  Subdivided result{batchPatches(patches, view, kRadius, splitDistanceUnit, table_, windings_), {}};
  result.batch.onTerrain = onTerrain;
  buffers_.upload(result.batch);
  useSubdivision(program_, result.batch, kDepth, kRadius);
  buffers_.subdivide();
  result.vertices = buffers_.readVertices();
  return result;
}

}  // namespace strata::icosahedral::test
