#include "pipeline/interval.hpp"

#include <strata/plugin/parameter.hpp>

namespace strata::loader {
namespace {

std::string withUnits(std::string text, const std::string& units) { return units.empty() ? text : text + " " + units; }

}  // namespace

bool Interval::contains(double value) const {
  const bool aboveLow = !low || (lowExclusive ? value > *low : value >= *low);
  const bool belowHigh = !high || (highExclusive ? value < *high : value <= *high);
  return aboveLow && belowHigh;
}

std::string Interval::str(const std::string& units) const {
  if (low && high)
    return withUnits(
        (lowExclusive ? "(" : "[") + formatValue(*low) + ", " + formatValue(*high) + (highExclusive ? ")" : "]"),
        units);
  if (low) return withUnits((lowExclusive ? "> " : ">= ") + formatValue(*low), units);
  if (high) return withUnits((highExclusive ? "< " : "<= ") + formatValue(*high), units);
  return "any value";
}

void requireWithin(double number, const Interval& allowed, const std::string& units, const YAML::Node& value,
                   const ValueContext& context) {
  if (allowed.contains(number)) return;
  const bool between = allowed.low && allowed.high;
  const std::string range = (between ? "in " : "") + allowed.str(units);
  // As the user wrote it: an integer beyond 2^53 would come back from the double another number.
  const std::string given = value.IsScalar() ? value.Scalar() : formatValue(number);
  throw context.source.error(value, context.nodeId,
                             context.label + " must be " + range + ", got " + withUnits(given, units),
                             "choose a value " + range);
}

}  // namespace strata::loader
