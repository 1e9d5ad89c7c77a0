#pragma once
#include <cstdint>
#include <strata/export.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// One draw of glMultiDrawElementsIndirect, laid out as OpenGL reads it from GL_DRAW_INDIRECT_BUFFER.
struct DrawElementsIndirectCommand {
  std::uint32_t count;
  std::uint32_t instanceCount;
  std::uint32_t firstIndex;
  std::int32_t baseVertex;
  std::uint32_t baseInstance;
};

}  // namespace strata
STRATA_EXPORTS_END
