#pragma once
#include <cstddef>
#include <vector>

#include <strata/date.hpp>
#include <strata/plugin/page_demand.hpp>

namespace strata::composite {

// Where a date falls in a time series: the two steps that bracket it, and how far it has gone from the earlier to
// the later, linearly in time (0 at the earlier's date, up to 1 at the later's).
struct Bracket {
  std::size_t earlier = 0;
  std::size_t later = 0;
  double fraction = 0.0;
};

// The dates of a series' steps ([Kooima 2008, §1.1, ch. 6], time-varying data), and which
// two a date falls between. Outside the series it holds the first or the last step: there is nothing to blend
// towards. A yearly series (a monthly climatology such as Blue Marble Next Generation's) repeats every calendar
// year: its steps are placed by their date's fraction of the year, and December's blends into January's across the
// new year.
class TemporalSeries {
 public:
  // `dates` one per step, in increasing order (of their fraction of the year when yearly); at least one.
  TemporalSeries(std::vector<DayNumber> dates, bool yearly);

  Bracket at(DayNumber date) const;
  // What each step's pages are wanted for at `bracket`: its two steps shown, the step beyond each of them
  // prefetched, so that moving on in either direction finds the next step loaded; the rest idle.
  std::vector<PageDemand> demands(const Bracket& bracket) const;

 private:
  Bracket bracketInside(double position) const;
  Bracket bracketAcrossNewYear(double position) const;

  std::vector<double> positions_;  // days, or fractions of the year when yearly
  bool yearly_ = false;
};

}  // namespace strata::composite
