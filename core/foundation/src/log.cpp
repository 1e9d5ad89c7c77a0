// The library's one way to speak to its host (strata/log.hpp).
#include <strata/log.hpp>

#include <cstdio>
#include <mutex>

namespace strata {
namespace {

std::mutex sinkLock;
LogSink currentSink;  // empty: the default, stderr

}  // namespace

const char* toString(LogLevel level) {
  switch (level) {
    case LogLevel::Debug: return "debug";
    case LogLevel::Info: return "info";
    case LogLevel::Warning: return "warning";
    case LogLevel::Error: return "error";
  }
  return "message";
}

std::string formatted(const LogMessage& message) {
  std::string text = std::string("strata: ") + toString(message.level) + ": " + message.text;
  if (!message.fix.empty()) text += "\n  fix: " + message.fix;
  return text;
}

LogSink setLogSink(LogSink sink) {
  std::lock_guard lock(sinkLock);
  std::swap(currentSink, sink);
  return sink;
}

void logMessage(const LogMessage& message) {
  std::lock_guard lock(sinkLock);
  if (currentSink)
    currentSink(message);
  else
    std::fprintf(stderr, "%s\n", formatted(message).c_str());
}

void logWarning(std::string text, std::string fix) { logMessage({LogLevel::Warning, std::move(text), std::move(fix)}); }

}  // namespace strata
