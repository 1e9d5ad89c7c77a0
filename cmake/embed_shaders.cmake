# Script mode: writes OUTPUT, a C++ file that defines strata::detail::builtinShaderSources().
string(REPLACE "|" ";" FILES "${FILES}")
set(body "")
foreach(file IN LISTS FILES)
  file(RELATIVE_PATH name ${ROOT} ${file})
  file(READ ${file} text)
  string(APPEND body "    {\"${name}\", R\"strata_glsl(${text})strata_glsl\"},\n")
endforeach()
file(WRITE ${OUTPUT}.tmp "// Generated from shaders/ by cmake/embed_shaders.cmake; edit the GLSL files instead.
#include <map>
#include <string>
namespace strata::detail {
const std::map<std::string, std::string>& builtinShaderSources() {
  static const std::map<std::string, std::string> sources{
${body}  };
  return sources;
}
}  // namespace strata::detail
")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
