#include "pipeline/parameter_parsing.hpp"

#include <algorithm>
#include <stdexcept>

#include "pipeline/interval.hpp"
#include "pipeline/suggestions.hpp"

namespace strata::loader {
namespace {

Interval declaredRange(const ParameterDeclaration& declaration) {
  return {declaration.minimum, declaration.maximum, declaration.exclusiveMinimum, false};
}

double parseReal(const YAML::Node& value, const ParameterDeclaration& declaration, const ValueContext& context) {
  const double number = readReal(value, context);
  requireWithin(number, declaredRange(declaration), declaration.units, value, context);
  return number;
}

std::int64_t parseInteger(const YAML::Node& value, const ParameterDeclaration& declaration,
                          const ValueContext& context) {
  const std::int64_t number = readInteger(value, context);
  requireWithin(static_cast<double>(number), declaredRange(declaration), declaration.units, value, context);
  return number;
}

std::vector<double> parseReals(const YAML::Node& value, const ParameterDeclaration& declaration,
                               const ValueContext& context) {
  const std::vector<double> numbers = readReals(value, context);
  if (declaration.count > 0 && numbers.size() != declaration.count)
    throw context.source.error(value, context.nodeId,
                               context.label + " expects " + std::to_string(declaration.count) + " numbers, got " +
                                   std::to_string(numbers.size()),
                               "give exactly " + std::to_string(declaration.count) + " numbers in brackets");
  for (std::size_t i = 0; i < numbers.size(); ++i)
    requireWithin(numbers[i], declaredRange(declaration), declaration.units, value[i], elementOf(context, i));
  return numbers;
}

std::string parseChoice(const YAML::Node& value, const ParameterDeclaration& declaration, const ValueContext& context) {
  std::string choice = readText(value, context);
  const auto& choices = declaration.choices;
  if (std::find(choices.begin(), choices.end(), choice) != choices.end()) return choice;
  throw context.source.error(
      value, context.nodeId,
      context.label + " is '" + choice + "', which is not one of " + quotedList(choices) + didYouMean(choice, choices),
      "choose one of " + quotedList(choices));
}

std::string parsePath(const YAML::Node& value, const ValueContext& context,
                      const std::filesystem::path& baseDirectory) {
  const std::string text = readText(value, context);
  if (text.empty())
    throw context.source.error(value, context.nodeId, context.label + " is empty", "give the path of a file");
  const std::filesystem::path path = (baseDirectory / text).lexically_normal();  // an absolute text wins
  std::error_code error;
  if (!std::filesystem::exists(path, error))
    throw context.source.error(
        value, context.nodeId, context.label + ": file not found: " + path.string(),
        "check the spelling; relative paths are read from the pipeline's directory " + baseDirectory.string());
  return path.string();
}

}  // namespace

ParameterValue parseParameter(const YAML::Node& value, const ParameterDeclaration& declaration,
                              const ValueContext& context, const std::filesystem::path& baseDirectory) {
  switch (declaration.type) {
    case ParameterType::Boolean: return readBoolean(value, context);
    case ParameterType::Integer: return parseInteger(value, declaration, context);
    case ParameterType::Real: return parseReal(value, declaration, context);
    case ParameterType::String: return readText(value, context);
    case ParameterType::Path: return parsePath(value, context, baseDirectory);
    case ParameterType::Choice: return parseChoice(value, declaration, context);
    case ParameterType::RealList: return parseReals(value, declaration, context);
    case ParameterType::DateList: return readDates(value, context);
    case ParameterType::Date: return readDate(value, context);
  }
  throw std::logic_error("parameter '" + declaration.name + "' has an unknown type");
}

ParameterValue defaultValue(const ParameterDeclaration& declaration) {
  const ParameterValue& value = *declaration.defaultValue;
  const auto* integer = std::get_if<std::int64_t>(&value);
  if (declaration.type == ParameterType::Real && integer) return static_cast<double>(*integer);
  return value;
}

}  // namespace strata::loader
