// Calendar dates for time series: ISO 8601 text to and from days since 2000-01-01T00:00:00Z, through the
// proleptic Gregorian calendar of <chrono>.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <regex>

#include <strata/date.hpp>

namespace strata {
namespace {

using std::chrono::day;
using std::chrono::days;
using std::chrono::month;
using std::chrono::sys_days;
using std::chrono::year;
using std::chrono::year_month_day;

constexpr sys_days kEpoch = year{2000} / 1 / 1;
constexpr double kSecondsADay = 86400.0;

int field(const std::ssub_match& match, int absent) { return match.matched ? std::stoi(match.str()) : absent; }

}  // namespace

std::optional<DayNumber> parseIsoDate(const std::string& text) {
  static const std::regex form(R"((\d{4})(?:-(\d{2})(?:-(\d{2})(?:T(\d{2}):(\d{2})(?::(\d{2}(?:\.\d+)?))?Z?)?)?)?)");
  std::smatch parts;
  if (!std::regex_match(text, parts, form)) return std::nullopt;
  const year_month_day date{year{field(parts[1], 0)}, month(unsigned(field(parts[2], 1))),
                            day(unsigned(field(parts[3], 1)))};
  const int hour = field(parts[4], 0), minute = field(parts[5], 0);
  const double second = parts[6].matched ? std::stod(parts[6].str()) : 0.0;
  if (!date.ok() || hour > 23 || minute > 59 || second >= 60.0) return std::nullopt;
  return double((sys_days(date) - kEpoch).count()) + (hour * 3600.0 + minute * 60.0 + second) / kSecondsADay;
}

std::string formatIsoDate(DayNumber value) {
  const double whole = std::floor(value);
  const long long seconds = std::llround((value - whole) * kSecondsADay);
  const year_month_day date{kEpoch + days(static_cast<long long>(whole) + seconds / 86400)};
  const long long of = seconds % 86400;
  char text[32];
  if (of == 0)
    std::snprintf(text, sizeof text, "%04d-%02u-%02u", int(date.year()), unsigned(date.month()), unsigned(date.day()));
  else
    std::snprintf(text, sizeof text, "%04d-%02u-%02uT%02lld:%02lld:%02lldZ", int(date.year()), unsigned(date.month()),
                  unsigned(date.day()), of / 3600, of / 60 % 60, of % 60);
  return text;
}

double yearFraction(DayNumber value) {
  const sys_days day{kEpoch + days(static_cast<long long>(std::floor(value)))};
  const year y = year_month_day{day}.year();
  const double start = double((sys_days(y / 1 / 1) - kEpoch).count());
  const double length = double((sys_days((y + std::chrono::years{1}) / 1 / 1) - sys_days(y / 1 / 1)).count());
  return (value - start) / length;
}

}  // namespace strata
