#include "pipeline/value_reading.hpp"

#include <charconv>
#include <cmath>
#include <optional>

#include <strata/date.hpp>

namespace strata::loader {
namespace {

// yaml-cpp gives untagged plain scalars the non-specific tag "?"; quoted ones get "!".
bool isPlainScalar(const YAML::Node& value) { return value.IsScalar() && value.Tag() == "?"; }

// from_chars does not take the leading '+' YAML allows (but "+-1" must stay wrong).
std::string_view withoutPlus(std::string_view text) {
  const bool plus = text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+';
  return plus ? text.substr(1) : text;
}

template <class Number>
std::optional<Number> parseNumber(std::string_view text) {
  text = withoutPlus(text);
  Number number{};
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return number;
}

std::optional<double> parseReal(std::string_view text) {
  // from_chars reads "inf" and "nan" too; a pipeline has no use for them.
  auto number = parseNumber<double>(text);
  if (number && !std::isfinite(*number)) return std::nullopt;
  return number;
}

Error wrongType(const YAML::Node& value, const ValueContext& context, const std::string& expected,
                const std::string& fix) {
  return context.source.error(value, context.nodeId,
                              context.label + " expects " + expected + ", got " + describe(value), fix);
}

}  // namespace

std::string describe(const YAML::Node& value) {
  if (value.IsMap()) return "a map";
  if (value.IsSequence()) return "a list";
  if (!value.IsScalar()) return "nothing";
  return isPlainScalar(value) ? "'" + value.Scalar() + "'" : "quoted text \"" + value.Scalar() + "\"";
}

bool readBoolean(const YAML::Node& value, const ValueContext& context) {
  const std::string text = isPlainScalar(value) ? value.Scalar() : std::string();
  if (text == "true" || text == "True" || text == "TRUE") return true;
  if (text == "false" || text == "False" || text == "FALSE") return false;
  throw wrongType(value, context, "true or false",
                  "write true or false without quotes; yes, no, on and off are not booleans here");
}

std::int64_t readInteger(const YAML::Node& value, const ValueContext& context) {
  if (auto number = isPlainScalar(value) ? parseNumber<std::int64_t>(value.Scalar()) : std::nullopt) return *number;
  throw wrongType(value, context, "an integer", "write a whole number without quotes, e.g. 3");
}

double readReal(const YAML::Node& value, const ValueContext& context) {
  if (auto number = isPlainScalar(value) ? parseReal(value.Scalar()) : std::nullopt) return *number;
  throw wrongType(value, context, "a number", "write a number without quotes, e.g. 300 or 2.5e6");
}

ValueContext elementOf(const ValueContext& list, std::size_t index) {
  return {list.source, "element " + std::to_string(index + 1) + " of " + list.label, list.nodeId};
}

std::vector<double> readReals(const YAML::Node& value, const ValueContext& context) {
  if (!value.IsSequence())
    throw wrongType(value, context, "a list of numbers", "write the numbers in brackets, e.g. [0, 0.5, 1]");
  std::vector<double> numbers;
  for (std::size_t i = 0; i < value.size(); ++i) numbers.push_back(readReal(value[i], elementOf(context, i)));
  return numbers;
}

std::string readText(const YAML::Node& value, const ValueContext& context) {
  if (value.IsScalar()) return value.Scalar();
  throw wrongType(value, context, "text", "write a single value, quoted if it contains ':' or '#'");
}

double readDate(const YAML::Node& value, const ValueContext& context) {
  const std::string text = value.IsScalar() ? value.Scalar() : std::string();
  if (const std::optional<DayNumber> days = parseIsoDate(text)) return *days;
  throw context.source.error(value, context.nodeId, context.label + " is " + describe(value) + ", which is not a date",
                             "write an ISO 8601 date in UTC: 2004-06-15, 2004-06, or 2004-06-15T12:30:00Z");
}

std::vector<double> readDates(const YAML::Node& value, const ValueContext& context) {
  if (!value.IsSequence())
    throw wrongType(value, context, "a list of dates", "write the dates in brackets, e.g. [2004-01-15, 2004-02-15]");
  std::vector<double> dates;
  for (std::size_t i = 0; i < value.size(); ++i) dates.push_back(readDate(value[i], elementOf(context, i)));
  return dates;
}

}  // namespace strata::loader
