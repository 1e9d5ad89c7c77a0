#include <stdexcept>
#include <utility>

#include <strata/plugin/parameter.hpp>

namespace strata {
namespace {

// Loading checked every value against its declaration, so asking for the wrong type is a bug in the
// node's code, not something a user can fix: a logic_error, not a strata::Error.
template <class T>
const T& typed(const ParameterValue& value, const std::string& name, const char* wanted) {
  if (const T* held = std::get_if<T>(&value)) return *held;
  throw std::logic_error("parameter '" + name + "' is not " + wanted + ": it holds " + formatValue(value));
}

}  // namespace

void ParameterSet::set(const std::string& name, ParameterValue value, SourceLocation where) {
  entries_.insert_or_assign(name, Entry{std::move(value), std::move(where)});
}

bool ParameterSet::has(const std::string& name) const { return entries_.count(name) != 0; }

bool ParameterSet::boolean(const std::string& name) const { return typed<bool>(value(name), name, "a boolean"); }

std::int64_t ParameterSet::integer(const std::string& name) const {
  return typed<std::int64_t>(value(name), name, "an integer");
}

double ParameterSet::real(const std::string& name) const { return typed<double>(value(name), name, "a real number"); }

const std::string& ParameterSet::string(const std::string& name) const {
  return typed<std::string>(value(name), name, "text");
}

std::filesystem::path ParameterSet::path(const std::string& name) const {
  return typed<std::string>(value(name), name, "a path");
}

const std::vector<double>& ParameterSet::reals(const std::string& name) const {
  return typed<std::vector<double>>(value(name), name, "a list of real numbers");
}

const ParameterValue& ParameterSet::value(const std::string& name) const { return entry(name).value; }

std::vector<std::string> ParameterSet::names() const {
  std::vector<std::string> names;
  for (const auto& entry : entries_) names.push_back(entry.first);
  return names;
}

const SourceLocation& ParameterSet::where(const std::string& name) const { return entry(name).where; }

const ParameterSet::Entry& ParameterSet::entry(const std::string& name) const {
  auto found = entries_.find(name);
  if (found == entries_.end()) throw std::logic_error("no parameter '" + name + "' in this set");
  return found->second;
}

}  // namespace strata
