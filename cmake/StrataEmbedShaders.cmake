# strata_embed_shaders(OUTPUT ROOT FILES...): compiles GLSL files into a C++ source that
# registers each under its path relative to ROOT, so programs never depend on files at run time.
function(strata_embed_shaders output root)
  set(inputs ${ARGN})
  string(REPLACE ";" "|" joined "${inputs}")  # a list would be split into separate arguments
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DROOT=${root} -DFILES=${joined}
            -P ${PROJECT_SOURCE_DIR}/cmake/embed_shaders.cmake
    DEPENDS ${inputs} ${PROJECT_SOURCE_DIR}/cmake/embed_shaders.cmake
    COMMENT "Embedding GLSL sources"
    VERBATIM)
endfunction()
