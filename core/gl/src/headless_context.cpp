// A headless OpenGL 4.5 core context through EGL: an EGL device when the driver offers one (NVIDIA's
// headless path), else Mesa's surfaceless platform (llvmpipe when there is no GPU).
#include <epoxy/egl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include <strata/gl/context.hpp>

namespace strata {
namespace {

class HeadlessContext : public GlContext {
 public:
  HeadlessContext(EGLDisplay display, EGLContext context, std::string description)
      : display_(display), context_(context), description_(std::move(description)) {}
  ~HeadlessContext() override {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
  void makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw std::runtime_error("eglMakeCurrent failed for the headless context");
  }
  std::string description() const override { return description_; }

 private:
  EGLDisplay display_;
  EGLContext context_;
  std::string description_;
};

bool hasClientExtension(const char* name) { return epoxy_has_egl_extension(EGL_NO_DISPLAY, name); }

// Devices in the order to try them: hardware first, Mesa's software device last.
std::vector<EGLDeviceEXT> eglDevices() {
  if (!hasClientExtension("EGL_EXT_device_enumeration")) return {};
  EGLint count = 0;
  if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0) return {};
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  eglQueryDevicesEXT(count, devices.data(), &count);
  std::vector<EGLDeviceEXT> hardware, software;
  for (EGLDeviceEXT device : devices) {
    const char* extensions = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
    bool isSoftware = extensions && std::string(extensions).find("EGL_MESA_device_software") != std::string::npos;
    (isSoftware ? software : hardware).push_back(device);
  }
  hardware.insert(hardware.end(), software.begin(), software.end());
  return hardware;
}

// An OpenGL 4.5 core context on `display`, or EGL_NO_CONTEXT.
EGLContext createCoreContext(EGLDisplay display, bool debug) {
  if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
  const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (!eglChooseConfig(display, configAttributes, &config, 1, &configs) || configs < 1) config = nullptr;
  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      4,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      5,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_CONTEXT_OPENGL_DEBUG,
                                      debug ? EGL_TRUE : EGL_FALSE,
                                      EGL_NONE};
  return eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
}

std::unique_ptr<GlContext> tryDisplay(EGLDisplay display, const std::string& platform, bool debug,
                                      std::string& attempts) {
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
    attempts += "\n  " + platform + ": no display";
    return nullptr;
  }
  EGLContext context = createCoreContext(display, debug);
  if (context == EGL_NO_CONTEXT) {
    attempts += "\n  " + platform + ": no OpenGL 4.5 core context (EGL error " + std::to_string(eglGetError()) + ")";
    eglTerminate(display);
    return nullptr;
  }
  const char* vendor = eglQueryString(display, EGL_VENDOR);
  auto result = std::make_unique<HeadlessContext>(display, context, platform + " (" + (vendor ? vendor : "?") + ")");
  result->makeCurrent();
  keepLoadedLibrariesResident();
  return result;
}

}  // namespace

std::unique_ptr<GlContext> createHeadlessContext(bool debug) {
  std::string attempts;
  for (EGLDeviceEXT device : eglDevices()) {
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (auto context = tryDisplay(display, "EGL device", debug, attempts)) return context;
  }
  if (hasClientExtension("EGL_MESA_platform_surfaceless")) {
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (auto context = tryDisplay(display, "EGL surfaceless", debug, attempts)) return context;
  }
  throw std::runtime_error(
      "no headless OpenGL 4.5 context could be created through EGL; tried:" +
      (attempts.empty() ? std::string("\n  (no EGL device or surfaceless platform offered)") : attempts) +
      "\n  fix: install Mesa's EGL driver (libegl-mesa0 libgl1-mesa-dri) or a GPU driver with EGL");
}

}  // namespace strata
