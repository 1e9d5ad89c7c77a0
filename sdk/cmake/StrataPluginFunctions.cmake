# strata_add_plugin(NAME SOURCES...) for plugins built out of tree against an installed Strata: a module
# named strata-NAME.so that the strata command loads from a directory on $STRATA_PLUGIN_PATH.
function(strata_add_plugin name)
  add_library(${name} MODULE ${ARGN})
  target_link_libraries(${name} PRIVATE Strata::core)
  target_compile_features(${name} PRIVATE cxx_std_20)
  set_target_properties(${name} PROPERTIES PREFIX "" OUTPUT_NAME "strata-${name}"
                        CXX_VISIBILITY_PRESET hidden)
endfunction()
