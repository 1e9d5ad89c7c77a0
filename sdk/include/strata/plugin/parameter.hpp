#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <variant>
#include <vector>

#include <strata/error.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// Date: an ISO 8601 date in the file (strata/date.hpp), held as its day number in a double; DateList: a list
// of them, held in a std::vector<double>.
enum class ParameterType { Boolean, Integer, Real, String, Path, Choice, RealList, DateList, Date };

const char* toString(ParameterType type);

using ParameterValue = std::variant<bool, std::int64_t, double, std::string, std::vector<double>>;

// One parameter of a node type or of the scene (strata/host/scene_settings.hpp), declared once: validation,
// error messages, `strata plugins --describe`, docs/reference/ and the viewer's controls all derive from this
// declaration. Nodes read their values typed, through ParameterBindings (strata/plugin/parameter_bindings.hpp).
struct ParameterDeclaration {
  std::string name;
  ParameterType type = ParameterType::Real;
  std::optional<ParameterValue> defaultValue;  // none: the parameter is required, unless `optional`
  std::optional<double> minimum;               // Integer, Real, RealList: inclusive bounds
  std::optional<double> maximum;
  std::string units;                 // "m", "deg", "" when dimensionless
  std::string doc;                   // one line
  std::vector<std::string> choices;  // Choice: the allowed values
  std::size_t count = 0;             // RealList: the exact number of values (0: any)
  // Whether a change takes effect in the next frame with nothing rebuilt (a uniform): the engine hands the
  // node its new parameters (Node::update) rather than reloading the pipeline (Engine::set).
  bool live = false;
  // With no default: the node needs no value and decides for itself without one (an override of what it
  // would work out); ParameterSet::has says whether one was given.
  bool optional = false;
  bool exclusiveMinimum = false;  // the value must lie above `minimum`, not at it (a camera's altitude > 0)
};

// A node's validated parameters: every declared parameter has a value of its declared type.
class ParameterSet {
 public:
  void set(const std::string& name, ParameterValue value, SourceLocation where);

  bool has(const std::string& name) const;
  bool boolean(const std::string& name) const;
  std::int64_t integer(const std::string& name) const;
  double real(const std::string& name) const;
  const std::string& string(const std::string& name) const;  // String, Path and Choice
  std::filesystem::path path(const std::string& name) const;
  const std::vector<double>& reals(const std::string& name) const;
  const ParameterValue& value(const std::string& name) const;
  std::vector<std::string> names() const;  // every parameter set, in name order
  // Where the value came from (the YAML scalar, a --set override, or the node for defaults).
  const SourceLocation& where(const std::string& name) const;

 private:
  struct Entry {
    ParameterValue value;
    SourceLocation where;
  };
  const Entry& entry(const std::string& name) const;
  std::map<std::string, Entry> entries_;
};

std::string formatValue(const ParameterValue& value);

}  // namespace strata
STRATA_EXPORTS_END
