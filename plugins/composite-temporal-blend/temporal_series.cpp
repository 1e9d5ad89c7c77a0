#include "temporal_series.hpp"

#include <algorithm>

namespace strata::composite {

TemporalSeries::TemporalSeries(std::vector<DayNumber> dates, bool yearly)
    : positions_(std::move(dates)), yearly_(yearly) {
  if (yearly_)
    for (double& position : positions_) position = yearFraction(position);
}

Bracket TemporalSeries::at(DayNumber date) const {
  const double position = yearly_ ? yearFraction(date) : date;
  const std::size_t last = positions_.size() - 1;
  if (position >= positions_.front() && position < positions_.back()) return bracketInside(position);
  if (yearly_ && last > 0) return bracketAcrossNewYear(position);
  return position < positions_.front() ? Bracket{0, 0, 0.0} : Bracket{last, last, 0.0};
}

// Between the first step and the last: the step at or before the date, and the next.
Bracket TemporalSeries::bracketInside(double position) const {
  const auto after = std::upper_bound(positions_.begin(), positions_.end(), position);
  const std::size_t later = std::size_t(after - positions_.begin()), earlier = later - 1;
  return {earlier, later, (position - positions_[earlier]) / (positions_[later] - positions_[earlier])};
}

// After the year's last step or before its first: from the last towards the first of the next year.
Bracket TemporalSeries::bracketAcrossNewYear(double position) const {
  const std::size_t last = positions_.size() - 1;
  const double sinceLast =
      position >= positions_.back() ? position - positions_.back() : position + 1.0 - positions_.back();
  return {last, 0, sinceLast / (positions_.front() + 1.0 - positions_.back())};
}

std::vector<PageDemand> TemporalSeries::demands(const Bracket& bracket) const {
  const std::size_t count = positions_.size();
  std::vector<PageDemand> demand(count, PageDemand::Idle);
  const auto prefetch = [&](std::size_t step, int direction) {
    const long long beyond = (long long)step + direction;
    if (yearly_ || (beyond >= 0 && beyond < (long long)count)) {
      PageDemand& d = demand[std::size_t((beyond + (long long)count) % (long long)count)];
      if (d == PageDemand::Idle) d = PageDemand::Prefetched;
    }
  };
  demand[bracket.earlier] = demand[bracket.later] = PageDemand::Shown;
  prefetch(bracket.earlier, -1);
  prefetch(bracket.later, +1);
  return demand;
}

}  // namespace strata::composite
