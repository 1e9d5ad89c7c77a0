#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "pipeline/source_map.hpp"

namespace strata::loader {

// What an error about one value needs: where the value came from and how to name it.
struct ValueContext {
  const SourceMap& source;
  std::string label;   // "parameter 'scale'", "camera 'altitude'"
  std::string nodeId;  // the node the value belongs to; empty outside nodes
};

// Strict readers of YAML scalars: each throws a strata::Error at the value, naming it, when the value is
// not of the type asked for. yaml-cpp's own conversions are too lenient for a format users should be
// able to trust (its as<bool>() takes yes/no/on/off, its as<double>() any stream-readable prefix), so:
//  - numbers and booleans must be plain scalars; a quoted "300" or a tagged !!str 300 is text;
//  - booleans are the YAML 1.2 words true/false (also True/TRUE/False/FALSE), nothing else;
//  - integers are decimal digits with an optional sign; reals also take a fraction and an exponent
//    (1.5, -2, 2.0e7, .5) but not .inf or .nan: every quantity in a pipeline is finite;
//  - text is any scalar, quoted or not (a number written where text is wanted is its own text).
bool readBoolean(const YAML::Node& value, const ValueContext& context);
std::int64_t readInteger(const YAML::Node& value, const ValueContext& context);
double readReal(const YAML::Node& value, const ValueContext& context);
std::vector<double> readReals(const YAML::Node& value, const ValueContext& context);  // a YAML sequence
std::string readText(const YAML::Node& value, const ValueContext& context);
// An ISO 8601 date or date and time in UTC (strata/date.hpp), as its day number; and a YAML sequence of them.
double readDate(const YAML::Node& value, const ValueContext& context);
std::vector<double> readDates(const YAML::Node& value, const ValueContext& context);

// The context of element `index` (from 0) of a list: "element 2 of parameter 'size'".
ValueContext elementOf(const ValueContext& list, std::size_t index);

// How a value reads in a message: 'high', quoted text "300", a list, a map, nothing.
std::string describe(const YAML::Node& value);

}  // namespace strata::loader
