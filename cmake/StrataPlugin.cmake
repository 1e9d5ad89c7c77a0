# strata_add_plugin(NAME SOURCES... [SHADERS GLSL...]): a loadable plugin module placed where the strata
# command looks, with its GLSL embedded (sdk/cmake/StrataPluginShaders.cmake). The same function ships in
# the installed package (sdk/cmake/StrataPluginFunctions.cmake).
include(${PROJECT_SOURCE_DIR}/sdk/cmake/StrataPluginShaders.cmake)

function(strata_add_plugin name)
  cmake_parse_arguments(PARSE_ARGV 1 plugin "" "" "SHADERS")
  add_library(${name} MODULE ${plugin_UNPARSED_ARGUMENTS})
  target_link_libraries(${name} PRIVATE Strata::core strata_warnings)
  set_target_properties(${name} PROPERTIES PREFIX "" OUTPUT_NAME "strata-${name}"
                        LIBRARY_OUTPUT_DIRECTORY ${STRATA_PLUGIN_OUTPUT_DIR}
                        CXX_VISIBILITY_PRESET hidden INSTALL_RPATH "$ORIGIN/../..")
  if(plugin_SHADERS)
    strata_plugin_shaders(${name} ${name} ${plugin_SHADERS})
  endif()
  install(TARGETS ${name} LIBRARY DESTINATION ${STRATA_PLUGIN_SUBDIR})
endfunction()
