# strata_add_plugin(NAME SOURCES... [SHADERS GLSL...]) for plugins built out of tree against an installed
# Strata: a module named strata-NAME.so that the strata command loads from a directory on
# $STRATA_PLUGIN_PATH. Its GLSL files are embedded in it, each named "NAME/<file>", and plugin_shaders.hpp
# declares strata::plugin::shaderSources() for its node declarations (StrataPluginShaders.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/StrataPluginShaders.cmake)

function(strata_add_plugin name)
  cmake_parse_arguments(PARSE_ARGV 1 plugin "" "" "SHADERS")
  add_library(${name} MODULE ${plugin_UNPARSED_ARGUMENTS})
  target_link_libraries(${name} PRIVATE Strata::core)
  target_compile_features(${name} PRIVATE cxx_std_20)
  set_target_properties(${name} PROPERTIES PREFIX "" OUTPUT_NAME "strata-${name}"
                        CXX_VISIBILITY_PRESET hidden)
  if(plugin_SHADERS)
    strata_plugin_shaders(${name} ${name} ${plugin_SHADERS})
  endif()
endfunction()
