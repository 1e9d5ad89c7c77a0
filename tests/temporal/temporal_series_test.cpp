// TemporalSeries: which two steps a date falls between and how far, in a plain series and in a yearly one that
// wraps across the new year; and which steps' pages each position wants.
#include <gtest/gtest.h>

#include "temporal_series.hpp"

namespace strata::composite {
namespace {

DayNumber day(const char* text) { return *parseIsoDate(text); }

const std::vector<DayNumber> kQuarters{day("2004-01-15"), day("2004-04-15"), day("2004-07-15"), day("2004-10-15")};

TEST(TemporalSeries, BlendsLinearlyInTimeBetweenTheBracketingSteps) {
  const TemporalSeries series(kQuarters, false);
  const Bracket onStep = series.at(day("2004-04-15"));
  EXPECT_EQ(onStep.earlier, 1u);
  EXPECT_EQ(onStep.later, 2u);
  EXPECT_DOUBLE_EQ(onStep.fraction, 0.0);
  const Bracket between = series.at(day("2004-05-16"));  // 31 of the 91 days from 15 April to 15 July
  EXPECT_EQ(between.earlier, 1u);
  EXPECT_EQ(between.later, 2u);
  EXPECT_DOUBLE_EQ(between.fraction, 31.0 / 91.0);
  EXPECT_NEAR(series.at(day("2004-07-14T23:59:59")).fraction, 1.0, 1e-6);  // meets the next step's 0
}

TEST(TemporalSeries, HoldsTheFirstAndLastStepsOutsideThePlainSeries) {
  const TemporalSeries series(kQuarters, false);
  for (const char* before : {"2003-06-01", "2004-01-14"}) {
    const Bracket bracket = series.at(day(before));
    EXPECT_EQ(bracket.earlier, 0u);
    EXPECT_EQ(bracket.later, 0u);
    EXPECT_EQ(bracket.fraction, 0.0);
  }
  for (const char* after : {"2004-10-15", "2030-01-01"}) {
    const Bracket bracket = series.at(day(after));
    EXPECT_EQ(bracket.earlier, 3u);
    EXPECT_EQ(bracket.later, 3u);
  }
}

TEST(TemporalSeries, YearlySeriesWrapsFromDecemberToJanuaryOfAnyYear) {
  const TemporalSeries series(kQuarters, true);
  // 15 October 2010 to 15 January 2011: 92 days; 1 December is 47 days in, 1 January 78.
  const Bracket december = series.at(day("2010-12-01"));
  EXPECT_EQ(december.earlier, 3u);
  EXPECT_EQ(december.later, 0u);
  EXPECT_NEAR(december.fraction, 47.0 / 92.0, 0.01);  // by fractions of the year: within a day
  const Bracket january = series.at(day("2011-01-01"));
  EXPECT_EQ(january.earlier, 3u);
  EXPECT_EQ(january.later, 0u);
  EXPECT_NEAR(january.fraction, 78.0 / 92.0, 0.01);
  EXPECT_GT(january.fraction, december.fraction);
  const Bracket may = series.at(day("1999-05-16"));  // a year the steps do not name
  EXPECT_EQ(may.earlier, 1u);
  EXPECT_EQ(may.later, 2u);
}

TEST(TemporalSeries, ShowsTheBracketAndPrefetchesTheStepBeyondEachSide) {
  using enum PageDemand;
  const TemporalSeries plain(kQuarters, false), yearly(kQuarters, true);
  EXPECT_EQ(plain.demands(plain.at(day("2004-05-01"))),
            (std::vector<PageDemand>{Prefetched, Shown, Shown, Prefetched}));
  EXPECT_EQ(plain.demands(plain.at(day("2004-02-01"))), (std::vector<PageDemand>{Shown, Shown, Prefetched, Idle}));
  EXPECT_EQ(plain.demands(plain.at(day("2005-01-01"))), (std::vector<PageDemand>{Idle, Idle, Prefetched, Shown}));
  EXPECT_EQ(yearly.demands(yearly.at(day("2004-12-01"))),
            (std::vector<PageDemand>{Shown, Prefetched, Prefetched, Shown}));
  const TemporalSeries single({day("2004-01-01")}, true);
  EXPECT_EQ(single.demands(single.at(day("2004-06-01"))), (std::vector<PageDemand>{Shown}));
}

}  // namespace
}  // namespace strata::composite
