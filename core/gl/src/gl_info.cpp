#include <string>

#include <strata/gl.hpp>
#include <strata/gl/context.hpp>
#include <strata/log.hpp>

namespace strata {
namespace {

std::string glString(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text ? reinterpret_cast<const char*>(text) : "";
}

bool verboseDebug = false;

void GLAPIENTRY logGlMessage(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei, const GLchar* message,
                             const void*) {
  bool important = type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
  if (!important && !verboseDebug) return;
  logMessage(
      {type == GL_DEBUG_TYPE_ERROR ? LogLevel::Error : LogLevel::Info,
       "GL " + std::string(type == GL_DEBUG_TYPE_ERROR ? "error " : "message ") + std::to_string(id) + ": " + message});
}

}  // namespace

GlInfo currentGlInfo() {
  return {glString(GL_VENDOR), glString(GL_RENDERER), glString(GL_VERSION), glString(GL_SHADING_LANGUAGE_VERSION)};
}

void enableGlDebugOutput(bool verbose) {
  verboseDebug = verbose;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // messages arrive on the call that caused them
  glDebugMessageCallback(logGlMessage, nullptr);
}

}  // namespace strata
