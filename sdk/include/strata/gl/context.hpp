#pragma once
#include <memory>
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

// An OpenGL 4.5 core context, current on the thread that made it.
class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual void makeCurrent() = 0;
  virtual std::string description() const = 0;  // platform and device, e.g. "EGL device (NVIDIA)"
};

// A context with no window, through EGL: an NVIDIA (or other) EGL device when one is present, else Mesa's
// surfaceless platform (llvmpipe without a GPU). Throws std::runtime_error saying what was tried.
std::unique_ptr<GlContext> createHeadlessContext(bool debug = false);

// Renderer, vendor and version strings of the current context.
struct GlInfo {
  std::string vendor;
  std::string renderer;
  std::string version;
  std::string shadingLanguage;
};
GlInfo currentGlInfo();

// Routes GL debug messages of the current context to the log (strata/log.hpp); errors always, others when verbose.
void enableGlDebugOutput(bool verbose);

// For a host that makes its own context (a window), in AddressSanitizer and ThreadSanitizer builds only
// (docs/robustness.md, "Sanitizers"): keeps every shared library loaded now, the GL driver's among them,
// loaded until the process ends. Mesa's EGL and GLX vendor libraries and its DRI driver leave allocations
// behind when they are unloaded (at eglTerminate, or at exit), which LeakSanitizer then reports as leaks of
// an unknown module that no suppression can name; resident, what they hold stays reachable, and a real
// leak's stack keeps its library's name. ThreadSanitizer ends the process when a library its suppressions
// ignore (the driver, tests/sanitizers/tsan.supp) is unloaded. Call once a GL context exists; headless
// contexts call it themselves. Does nothing in other builds.
void keepLoadedLibrariesResident();

}  // namespace strata
STRATA_EXPORTS_END
