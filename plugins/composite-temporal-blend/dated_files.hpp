#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <strata/date.hpp>
#include <strata/error.hpp>

namespace strata::composite {

// A file of a time series and the date its name gives.
struct DatedFile {
  std::filesystem::path path;
  DayNumber date = 0.0;
};

// The files a file-name pattern matches, by the dates their names give, earliest first: `pattern` is a path
// whose last part may hold the fields %Y (4-digit year), %m (2-digit month), %d (2-digit day of the month),
// %j (3-digit day of the year), `*` (any text) and %% (a percent sign), so that Blue Marble Next Generation's
// monthly mosaics are "bmng/world.%Y%m.3x21600x10800.jpg". Missing fields take January and the 1st. Relative
// patterns resolve against `directory`. Throws strata::Error at `where` when the pattern has no date field,
// when nothing matches, when a name gives no real day, or when two files give the same date.
std::vector<DatedFile> datedFiles(const std::string& pattern, const std::filesystem::path& directory,
                                  const SourceLocation& where);

}  // namespace strata::composite
