#include "dated_files.hpp"

#include <algorithm>
#include <map>
#include <regex>

namespace strata::composite {
namespace {

// The file-name pattern as a regular expression, and which capture holds which field.
struct NamePattern {
  std::regex expression;
  std::map<char, int> fields;  // 'Y', 'm', 'd', 'j' -> capture index
};

NamePattern namePattern(const std::string& name, const SourceLocation& where) {
  static const std::map<char, std::string> digits{
      {'Y', "(\\d{4})"}, {'m', "(\\d{2})"}, {'d', "(\\d{2})"}, {'j', "(\\d{3})"}};
  std::string expression;
  NamePattern pattern;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (c == '%' && i + 1 < name.size() && (digits.contains(name[i + 1]) || name[i + 1] == '%')) {
      const char field = name[++i];
      if (field == '%') {
        expression += "%";
        continue;
      }
      if (pattern.fields.contains(field))
        throw Error(where, "the file-name pattern has %" + std::string(1, field) + " twice",
                    "give each date field once");
      pattern.fields[field] = int(pattern.fields.size()) + 1;
      expression += digits.at(field);
    } else if (c == '*') {
      expression += ".*";
    } else {
      if (std::string("\\^$.|?+()[]{}").find(c) != std::string::npos) expression += '\\';
      expression += c;
    }
  }
  if (!pattern.fields.contains('Y') && !pattern.fields.contains('m') && !pattern.fields.contains('j'))
    throw Error(where, "the file-name pattern '" + name + "' has no date field",
                "mark where the date is in the file names with %Y, %m, %d or %j, e.g. world.%Y%m.jpg");
  pattern.expression = std::regex(expression);
  return pattern;
}

// The date a matched name gives, or none where it names no real day.
std::optional<DayNumber> dateOf(const std::smatch& match, const NamePattern& pattern) {
  const auto field = [&](char name, const char* absent) {
    return pattern.fields.contains(name) ? match[std::size_t(pattern.fields.at(name))].str() : std::string(absent);
  };
  const std::string year = field('Y', "2000");
  if (pattern.fields.contains('j')) {
    const int dayOfYear = std::stoi(field('j', "001"));
    const std::optional<DayNumber> start = parseIsoDate(year);
    const std::optional<DayNumber> next = parseIsoDate(std::to_string(std::stoi(year) + 1));
    if (!start || !next || dayOfYear < 1 || *start + dayOfYear - 1 >= *next) return std::nullopt;
    return *start + dayOfYear - 1;
  }
  return parseIsoDate(year + "-" + field('m', "01") + "-" + field('d', "01"));
}

}  // namespace

std::vector<DatedFile> datedFiles(const std::string& pattern, const std::filesystem::path& directory,
                                  const SourceLocation& where) {
  const std::filesystem::path full = (directory / pattern).lexically_normal();
  const std::filesystem::path folder = full.parent_path();
  const NamePattern names = namePattern(full.filename().string(), where);
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw Error(where, "the folder of the file-name pattern, " + folder.string() + ", does not exist",
                "check the path; relative patterns are read from the pipeline's directory " + directory.string());
  std::vector<DatedFile> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    std::smatch match;
    if (!entry.is_regular_file() || !std::regex_match(name, match, names.expression)) continue;
    const std::optional<DayNumber> date = dateOf(match, names);
    if (!date)
      throw Error(where, "the file '" + name + "' matches the pattern but its name gives no real day",
                  "rename it, or narrow the pattern so that it does not match");
    files.push_back({entry.path(), *date});
  }
  if (files.empty())
    throw Error(
        where, "no file in " + folder.string() + " matches '" + full.filename().string() + "'",
        "check the pattern's fixed parts against the file names (%Y, %m, %d, %j: the date's digits; *: any text)");
  std::sort(files.begin(), files.end(), [](const DatedFile& a, const DatedFile& b) {
    return a.date != b.date ? a.date < b.date : a.path < b.path;  // names too: the same message every time
  });
  for (std::size_t i = 1; i < files.size(); ++i)
    if (files[i].date == files[i - 1].date)
      throw Error(where,
                  "'" + files[i - 1].path.filename().string() + "' and '" + files[i].path.filename().string() +
                      "' give the same date, " + formatIsoDate(files[i].date),
                  "a series has one file per date: narrow the pattern or move one of them");
  return files;
}

}  // namespace strata::composite
