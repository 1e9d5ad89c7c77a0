# Warnings for every Strata target; -Werror when STRATA_WERROR is on (CI).
add_library(strata_warnings INTERFACE)
target_compile_options(strata_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                       -Wno-sign-conversion
                       -Wno-missing-field-initializers  # aggregates rely on member defaults
                       $<$<BOOL:${STRATA_WERROR}>:-Werror>)
if(STRATA_SANITIZE)
  target_compile_options(strata_warnings INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(strata_warnings INTERFACE -fsanitize=address,undefined)
endif()
