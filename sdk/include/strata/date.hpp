#pragma once
#include <optional>
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

// A moment in UTC as days since 2000-01-01T00:00:00Z, negative before it: the unit time series are stepped
// in (composite.temporal_blend, the scene's `date:`). A double keeps better than a millisecond over ten
// thousand years. Leap seconds are not counted (POSIX time).
using DayNumber = double;

// Reads an ISO 8601 calendar date or date and time in UTC, as pipelines write them:
//   2004-06-15   2004-06   2004   2004-06-15T12:30   2004-06-15T12:30:45.5Z
// A month alone means its first day, a year alone its 1 January. Years 0000 to 9999. None when the text is
// not one of these forms or names no real day (2004-02-30, month 13, hour 24).
std::optional<DayNumber> parseIsoDate(const std::string& text);

// The moment as ISO 8601, to the second: "2004-06-15T12:30:45Z"; the date alone when it is midnight.
std::string formatIsoDate(DayNumber days);

// Where the moment falls in its calendar year, from 0 at 1 January 00:00 to just below 1 at the end of
// 31 December, for series that repeat every year (a monthly climatology such as Blue Marble's).
double yearFraction(DayNumber days);

}  // namespace strata
STRATA_EXPORTS_END
