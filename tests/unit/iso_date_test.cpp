// ISO 8601 dates as day numbers since 2000-01-01T00:00:00Z (strata/date.hpp), against day counts worked out by
// hand and the Gregorian calendar's leap-year rules.
#include <gtest/gtest.h>

#include <strata/date.hpp>

namespace strata {
namespace {

TEST(IsoDate, ReadsEveryFormPipelinesUse) {
  EXPECT_EQ(parseIsoDate("2000-01-01"), 0.0);
  EXPECT_EQ(parseIsoDate("2000"), 0.0);
  EXPECT_EQ(parseIsoDate("2000-03"), 60.0);  // 2000 is a leap year: 31 + 29 days to 1 March
  EXPECT_EQ(parseIsoDate("2001-01-01"), 366.0);
  EXPECT_EQ(parseIsoDate("1999-12-31"), -1.0);
  EXPECT_EQ(parseIsoDate("2004-06-15T12:00"), 1627.5);  // 4 years of 1461 days, then 166 to 15 June
  EXPECT_DOUBLE_EQ(*parseIsoDate("2004-06-15T06:30:36Z"), 1627.0 + (6 * 3600 + 30 * 60 + 36) / 86400.0);
  EXPECT_DOUBLE_EQ(*parseIsoDate("2004-06-15T00:00:00.5"), 1627.0 + 0.5 / 86400.0);
}

TEST(IsoDate, RefusesWhatNamesNoDay) {
  for (const char* text : {"2004-02-30", "1900-02-29", "2004-13-01", "2004-00-10", "2004-06-15T24:00", "2004-6-15",
                           "15/06/2004", "2004-06-15 12:00", "", "June", "2004-06-15T12:60", "2004-06-15T12:00:60"})
    EXPECT_FALSE(parseIsoDate(text)) << text;
  EXPECT_TRUE(parseIsoDate("2000-02-29"));  // divisible by 400: a leap year
}

TEST(IsoDate, FormatsToTheSecondAndRoundTrips) {
  EXPECT_EQ(formatIsoDate(1627.0), "2004-06-15");
  EXPECT_EQ(formatIsoDate(1627.5), "2004-06-15T12:00:00Z");
  EXPECT_EQ(formatIsoDate(-1.0), "1999-12-31");
  EXPECT_EQ(formatIsoDate(*parseIsoDate("2004-12-31T23:59:59.9999")), "2005-01-01");  // rounds to the second
  for (const char* text : {"1970-01-01", "2004-02-29T06:07:08Z", "2099-12-31T23:59:59Z"})
    EXPECT_EQ(formatIsoDate(*parseIsoDate(text)), text);
}

TEST(IsoDate, YearFractionRunsFromZeroAtNewYear) {
  EXPECT_DOUBLE_EQ(yearFraction(*parseIsoDate("2004-01-01")), 0.0);
  EXPECT_DOUBLE_EQ(yearFraction(*parseIsoDate("2004-07-02")), 183.0 / 366.0);  // 2004 has 366 days
  EXPECT_DOUBLE_EQ(yearFraction(*parseIsoDate("2003-07-02")), 182.0 / 365.0);
  EXPECT_NEAR(yearFraction(*parseIsoDate("1999-12-31T23:59:59")), 1.0, 1e-7);
  EXPECT_LT(yearFraction(*parseIsoDate("1999-12-31T23:59:59")), 1.0);
}

}  // namespace
}  // namespace strata
