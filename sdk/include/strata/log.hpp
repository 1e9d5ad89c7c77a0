#pragma once
// What the library has to tell its host beyond the errors it throws: data it works around (a page that
// cannot be read, a file's stored ranges it ignores), a frame that did not settle, GL debug messages.
// The library never writes to stderr itself: every message goes to one sink, which a host replaces to
// route messages where its users look (a viewer's panel, a log file, Python's logging). The default sink
// writes each message to stderr as "strata: warning: TEXT" and, when there is one, "  fix: FIX".
#include <functional>
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

enum class LogLevel { Debug, Info, Warning, Error };

const char* toString(LogLevel level);  // "debug", "info", "warning", "error"

// One message: what happened and what it costs, and, where the user can do something, what.
struct LogMessage {
  LogLevel level = LogLevel::Warning;
  std::string text;
  std::string fix{};
};

// "strata: warning: TEXT", with "\n  fix: FIX" when there is a fix: what the default sink prints.
std::string formatted(const LogMessage& message);

using LogSink = std::function<void(const LogMessage&)>;

// Sends every later message, from any thread, to `sink` (called under a lock, one message at a time, so
// it must not log itself); an empty sink restores the default. Returns the sink it replaces (empty for
// the default), so that a host or a test can put it back.
LogSink setLogSink(LogSink sink);

void logMessage(const LogMessage& message);
void logWarning(std::string text, std::string fix = {});

}  // namespace strata
STRATA_EXPORTS_END
