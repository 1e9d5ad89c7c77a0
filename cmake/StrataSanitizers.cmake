# Sanitizers for every target the build makes (libraries, plugins, apps, tests), so that a plugin loaded
# into a sanitized strata is checked too. CMakePresets.json names the two combinations CI and developers
# use: "address,undefined" (AddressSanitizer with LeakSanitizer, and UndefinedBehaviorSanitizer) and
# "thread" (ThreadSanitizer); the two cannot share a process.
set(STRATA_SANITIZERS "" CACHE STRING
    "Sanitizers to build with, as -fsanitize= takes them: address,undefined or thread (empty: none)")
if(STRATA_SANITIZERS)
  # No recovery: the first finding ends the process with an error, so a test cannot pass over it.
  add_compile_options(-fsanitize=${STRATA_SANITIZERS} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${STRATA_SANITIZERS})
endif()
