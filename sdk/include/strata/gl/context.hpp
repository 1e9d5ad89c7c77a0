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

}  // namespace strata
STRATA_EXPORTS_END
