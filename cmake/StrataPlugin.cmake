# strata_add_plugin(NAME SOURCES...): a loadable plugin module placed where the strata command looks.
# The same function ships in the installed package (sdk/cmake/StrataPluginFunctions.cmake).
function(strata_add_plugin name)
  add_library(${name} MODULE ${ARGN})
  target_link_libraries(${name} PRIVATE Strata::core strata_warnings)
  set_target_properties(${name} PROPERTIES PREFIX "" OUTPUT_NAME "strata-${name}"
                        LIBRARY_OUTPUT_DIRECTORY ${STRATA_PLUGIN_OUTPUT_DIR}
                        CXX_VISIBILITY_PRESET hidden INSTALL_RPATH "$ORIGIN/../..")
  install(TARGETS ${name} LIBRARY DESTINATION ${STRATA_PLUGIN_SUBDIR})
endfunction()
