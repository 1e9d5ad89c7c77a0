#pragma once
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "pipeline/value_reading.hpp"

namespace strata::loader {

// The values a number may take: a bound on either side or none, each inclusive or exclusive. Declared
// parameters have inclusive bounds; the camera needs exclusive ones (altitude > 0).
struct Interval {
  std::optional<double> low;
  std::optional<double> high;
  bool lowExclusive = false;
  bool highExclusive = false;

  static Interval closed(std::optional<double> low, std::optional<double> high) { return {low, high, false, false}; }
  static Interval above(double low) { return {low, std::nullopt, true, false}; }
  static Interval any() { return {std::nullopt, std::nullopt, false, false}; }

  bool contains(double value) const;
  // "[0, 90] deg", "> 0 m", "<= 1", "any value"
  std::string str(const std::string& units) const;
};

// Throws a strata::Error at `value` naming the interval and units when `number` lies outside it.
void requireWithin(double number, const Interval& allowed, const std::string& units, const YAML::Node& value,
                   const ValueContext& context);

}  // namespace strata::loader
