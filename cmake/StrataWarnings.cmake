# Warnings for every Strata target; -Werror when STRATA_WERROR is on (CI).
add_library(strata_warnings INTERFACE)
target_compile_options(strata_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                       -Wno-sign-conversion
                       -Wno-missing-field-initializers  # aggregates rely on member defaults
                       $<$<BOOL:${STRATA_WERROR}>:-Werror>)
# GCC's flow analysis sees the sanitizers' instrumentation and warns of uninitialised reads inside libstdc++
# (std::function in <regex>) that the plain build, which keeps the warning, proves absent.
if(STRATA_SANITIZERS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(strata_warnings INTERFACE -Wno-maybe-uninitialized)
endif()
