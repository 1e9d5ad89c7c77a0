#include "date_sweep.hpp"

#include <regex>

#include <strata/error.hpp>

namespace strata::cli {
namespace {

// One %d field with an optional zero-padded width, and nothing else but doubled percent signs around it.
const std::regex kFramePattern(R"(((?:[^%]|%%)*)%(0?\d{0,2})d((?:[^%]|%%)*))");

std::string undoubled(const std::string& text) { return std::regex_replace(text, std::regex("%%"), "%"); }

}  // namespace

DateSweep parseDateSweep(const std::string& interval, int frames) {
  const std::size_t slash = interval.find('/');
  const std::optional<DayNumber> first =
      slash == std::string::npos ? std::nullopt : parseIsoDate(interval.substr(0, slash));
  const std::optional<DayNumber> last =
      slash == std::string::npos ? std::nullopt : parseIsoDate(interval.substr(slash + 1));
  if (!first || !last || *last < *first)
    throw Error(SourceLocation{"--dates"}, "'" + interval + "' is not an interval of two dates, the earlier first",
                "write FIRST/LAST in ISO 8601, e.g. --dates 2004-01-01/2004-12-31");
  if (frames < 2)
    throw Error(SourceLocation{"--frames"},
                "a sweep through dates takes at least 2 frames, got " + std::to_string(frames),
                "give --frames N with N >= 2, e.g. --frames 48 for a frame a week through a year");
  return {*first, *last, frames};
}

void checkFramePattern(const std::string& pattern) {
  if (!std::regex_match(pattern, kFramePattern))
    throw Error(
        SourceLocation{"-o"}, "'" + pattern + "' does not name each frame's file",
        "give -o a pattern with one frame number field, e.g. -o out/year_%04d.png (write %% for a percent sign)");
}

std::string frameFileName(const std::string& pattern, int frame) {
  std::smatch parts;
  std::regex_match(pattern, parts, kFramePattern);
  const std::string width = parts[2].str();
  std::string number = std::to_string(frame);
  const std::size_t digits = width.empty() ? 0 : std::size_t(std::stoi(width));
  if (number.size() < digits) number.insert(0, digits - number.size(), width.front() == '0' ? '0' : ' ');
  return undoubled(parts[1].str()) + number + undoubled(parts[3].str());
}

}  // namespace strata::cli
