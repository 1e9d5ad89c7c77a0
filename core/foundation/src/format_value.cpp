#include <charconv>
#include <type_traits>

#include <strata/plugin/parameter.hpp>

namespace strata {
namespace {

// The shortest text that reads back as the same double: 0.25, 300, 2e+07.
std::string formatReal(double value) {
  char buffer[32];
  auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc{} ? std::string(buffer, end) : std::to_string(value);
}

std::string formatReals(const std::vector<double>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + formatReal(values[i]);
  return text + "]";
}

}  // namespace

// Values as a user would write them in a pipeline, for messages and `strata plugins --describe`. Text
// is written plain, without quotes, as in YAML.
std::string formatValue(const ParameterValue& value) {
  return std::visit(
      [](const auto& held) -> std::string {
        using T = std::decay_t<decltype(held)>;
        if constexpr (std::is_same_v<T, bool>)
          return held ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::int64_t>)
          return std::to_string(held);
        else if constexpr (std::is_same_v<T, double>)
          return formatReal(held);
        else if constexpr (std::is_same_v<T, std::string>)
          return held;
        else
          return formatReals(held);
      },
      value);
}

}  // namespace strata
