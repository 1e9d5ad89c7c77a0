// datedFiles: a time series' files found by a file-name pattern, dated by their names, earliest first, and the
// errors a pattern that finds no series gets.
#include <gtest/gtest.h>

#include "dated_files.hpp"
#include "temporary_directory.hpp"

namespace strata::composite {
namespace {

class DatedFiles : public ::testing::Test {
 protected:
  void touch(const std::string& name) const { directory_.write(name, "x"); }
  std::vector<DatedFile> find(const std::string& pattern) const {
    return datedFiles(pattern, directory_.path(), SourceLocation{"p.yaml", 7, 12});
  }
  // The message of the error the pattern gets, after checking it is at the parameter.
  std::string problemOf(const std::string& pattern) const {
    try {
      find(pattern);
    } catch (const Error& error) {
      EXPECT_EQ(error.where().line, 7);
      EXPECT_FALSE(error.fix().empty());
      return error.problem();
    }
    ADD_FAILURE() << pattern << " was accepted";
    return {};
  }

  test::TemporaryDirectory directory_;
};

TEST_F(DatedFiles, FindsBlueMarbleStyleMonthsInDateOrder) {
  for (const char* name : {"world.200412.3x5400x2700.jpg", "world.200401.3x5400x2700.jpg",
                           "world.200402.3x5400x2700.jpg", "world.topo.200401.jpg", "readme.txt"})
    touch(name);
  const std::vector<DatedFile> files = find("world.%Y%m.*.jpg");
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].path.filename(), "world.200401.3x5400x2700.jpg");
  EXPECT_EQ(files[0].date, *parseIsoDate("2004-01-01"));
  EXPECT_EQ(files[1].date, *parseIsoDate("2004-02-01"));
  EXPECT_EQ(files[2].date, *parseIsoDate("2004-12-01"));
}

TEST_F(DatedFiles, ReadsDaysOfTheYearAndFullDatesInSubfolders) {
  std::filesystem::create_directory(directory_.path() / "ice");
  for (const char* name : {"ice/thickness_2010_032.tif", "ice/thickness_2010_001.tif", "ice/thickness_2012_366.tif"})
    touch(name);
  const std::vector<DatedFile> byDay = find("ice/thickness_%Y_%j.tif");
  ASSERT_EQ(byDay.size(), 3u);
  EXPECT_EQ(byDay[1].date, *parseIsoDate("2010-02-01"));
  EXPECT_EQ(byDay[2].date, *parseIsoDate("2012-12-31"));  // 2012 is a leap year
  touch("scene_20040615.tif");
  EXPECT_EQ(find("scene_%Y%m%d.tif").front().date, *parseIsoDate("2004-06-15"));
}

TEST_F(DatedFiles, PatternsThatFindNoSeriesAreErrorsAtTheParameter) {
  touch("world.200401.a.jpg");
  touch("world.200401.b.jpg");
  touch("world.200413.c.jpg");
  touch("cover_2010_366.tif");
  EXPECT_EQ(problemOf("world.jpg"), "the file-name pattern 'world.jpg' has no date field");
  EXPECT_EQ(problemOf("world.%Y%m.a.png").substr(0, 11), "no file in ");
  EXPECT_EQ(problemOf("world.%Y%m.c.jpg"),
            "the file 'world.200413.c.jpg' matches the pattern but its name gives no real day");
  EXPECT_EQ(problemOf("cover_%Y_%j.tif"),
            "the file 'cover_2010_366.tif' matches the pattern but its name gives no real day");
  EXPECT_EQ(problemOf("world.%Y%m.[ab].jpg").substr(0, 11), "no file in ");  // brackets are plain text
  EXPECT_EQ(problemOf("world.%Y%m.%m.jpg"), "the file-name pattern has %m twice");
  EXPECT_NE(problemOf("missing/world.%Y%m.jpg").find("does not exist"), std::string::npos);
  EXPECT_EQ(problemOf("world.%Y%m.*.jpg"),
            "the file 'world.200413.c.jpg' matches the pattern but its name gives no real day");
  EXPECT_EQ(problemOf("world.%Y%m.?.jpg").substr(0, 11), "no file in ");  // ? is plain text too
  touch("world.200401.z.png");
  touch("world.200401.y.png");
  EXPECT_EQ(problemOf("world.%Y%m.*.png"),
            "'world.200401.y.png' and 'world.200401.z.png' give the same date, 2004-01-01");
}

}  // namespace
}  // namespace strata::composite
