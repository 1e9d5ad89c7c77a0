# With STRATA_FUZZ, every target is instrumented for libFuzzer's coverage guidance; the fuzz executables
# (tests/fuzz) link libFuzzer's own main.
if(STRATA_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "STRATA_FUZZ needs clang, whose libFuzzer the fuzz targets link: CXX=clang++ cmake ...")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
