#pragma once
#include <strata/export.hpp>

// Not part of the SDK: exported from libstrata_core for Strata's own tests and tools.
STRATA_EXPORTS_BEGIN
namespace strata {

// In AddressSanitizer and ThreadSanitizer builds only (docs/robustness.md, "Sanitizers"): keeps every
// shared library loaded now, the GL driver's among them, loaded until the process ends. Mesa's EGL and GLX
// vendor libraries and its DRI driver leave allocations behind when they are unloaded (at eglTerminate, or
// at exit), which LeakSanitizer then reports as leaks of an unknown module that no suppression can name;
// resident, what they hold stays reachable, and a real leak's stack keeps its library's name. ThreadSanitizer
// ends the process when a library its suppressions ignore (the driver, tests/sanitizers/tsan.supp) is
// unloaded. Call once a GL context exists. Does nothing in other builds.
void keepLoadedLibrariesResident();

}  // namespace strata
STRATA_EXPORTS_END
