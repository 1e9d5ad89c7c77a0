# Script mode, run by strata_plugin_shaders: writes OUTPUT, a C++ file that defines
# strata::plugin::shaderSources() with each of FILES ('|'-separated) named PREFIX/<path below ROOT>.
string(REPLACE "|" ";" FILES "${FILES}")
set(body "")
foreach(file IN LISTS FILES)
  file(RELATIVE_PATH name ${ROOT} ${file})
  file(READ ${file} text)
  string(APPEND body "      {\"${PREFIX}/${name}\", R\"strata_glsl(${text})strata_glsl\"},\n")
endforeach()
file(WRITE ${OUTPUT}.tmp "// Generated from plugin ${PREFIX}'s GLSL files by StrataEmbedPluginShaders.cmake; edit those instead.
#include \"plugin_shaders.hpp\"

namespace strata::plugin {
const std::map<std::string, std::string>& shaderSources() {
  static const std::map<std::string, std::string> sources{
${body}  };
  return sources;
}
}  // namespace strata::plugin
")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUTPUT}.tmp)
