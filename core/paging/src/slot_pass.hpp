#pragma once
#include <strata/gl.hpp>
#include <strata/gl/shader_program.hpp>

namespace strata::paging {

// Runs `program`, a compute pass of 16 x 16 invocations a group, over every texel of `slot` of the array texture
// `atlas` of `format`, bound as image 0 (read and write) with its uniform `slot`; on its return the texels it
// wrote may be sampled and the slot uploaded to again. What pages take right after their upload
// (SceneLinearPages, ValueSlopesPages). On the GL thread.
void runOverSlot(const ShaderProgram& program, GLuint atlas, GLenum format, int slot);

}  // namespace strata::paging
