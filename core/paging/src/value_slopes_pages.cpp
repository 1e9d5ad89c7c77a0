#include "value_slopes_pages.hpp"

#include <strata/gl/shader_library.hpp>

#include "slot_pass.hpp"

namespace strata::paging {

ValueSlopesPages::ValueSlopesPages()
    : program_({{GL_COMPUTE_SHADER, "strata/page_value_slopes.comp",
                 ShaderLibrary().expand("strata/page_value_slopes.comp", {})}}) {}

void ValueSlopesPages::compute(GLuint atlas, int slot) const { runOverSlot(program_, atlas, GL_RGBA32F, slot); }

}  // namespace strata::paging
