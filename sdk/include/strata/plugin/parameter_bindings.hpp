#pragma once
#include <any>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <strata/plugin/parameter.hpp>

namespace strata {

// How a setting's C++ type is held in a ParameterValue, and the parameter type it declares. The member's
// type decides, except that a double may be declared a Date and a list of doubles a DateList.
template <class T>
struct ParameterTraits;

template <>
struct ParameterTraits<bool> {
  static ParameterType type(const ParameterDeclaration&) { return ParameterType::Boolean; }
  static ParameterValue held(bool value) { return value; }
  static bool from(const ParameterValue& value) { return std::get<bool>(value); }
};

template <>
struct ParameterTraits<std::int64_t> {
  static ParameterType type(const ParameterDeclaration&) { return ParameterType::Integer; }
  static ParameterValue held(std::int64_t value) { return value; }
  static std::int64_t from(const ParameterValue& value) { return std::get<std::int64_t>(value); }
};

template <>
struct ParameterTraits<int> {
  static ParameterType type(const ParameterDeclaration&) { return ParameterType::Integer; }
  static ParameterValue held(int value) { return std::int64_t(value); }
  static int from(const ParameterValue& value) { return int(std::get<std::int64_t>(value)); }
};

template <>
struct ParameterTraits<double> {
  static ParameterType type(const ParameterDeclaration& declared) {
    return declared.type == ParameterType::Date ? ParameterType::Date : ParameterType::Real;
  }
  static ParameterValue held(double value) { return value; }
  static double from(const ParameterValue& value) { return std::get<double>(value); }
};

template <>
struct ParameterTraits<std::string> {
  static ParameterType type(const ParameterDeclaration& declared) {
    return declared.choices.empty() ? ParameterType::String : ParameterType::Choice;
  }
  static ParameterValue held(const std::string& value) { return value; }
  static std::string from(const ParameterValue& value) { return std::get<std::string>(value); }
};

template <>
struct ParameterTraits<std::filesystem::path> {
  static ParameterType type(const ParameterDeclaration&) { return ParameterType::Path; }
  static ParameterValue held(const std::filesystem::path& value) { return value.string(); }
  static std::filesystem::path from(const ParameterValue& value) { return std::get<std::string>(value); }
};

template <>
struct ParameterTraits<std::vector<double>> {
  static ParameterType type(const ParameterDeclaration& declared) {
    return declared.type == ParameterType::DateList ? ParameterType::DateList : ParameterType::RealList;
  }
  static ParameterValue held(const std::vector<double>& value) { return value; }
  static std::vector<double> from(const ParameterValue& value) { return std::get<std::vector<double>>(value); }
};

// The parameters of a node type (or of a section of the scene), each declared once and bound to the member
// of a settings struct that holds it: the member's type gives the parameter's type, and its initialiser in
// `Settings` the default, so a default is written in one place with the comment that says why. The node
// reads its settings typed (`read`), never by a string key:
//
//   struct Lighting { double azimuth = 315.0; /* light from the north-west: relief reads as raised */ };
//   const ParameterBindings<Lighting>& lightingParameters() {
//     static const auto bindings = ParameterBindings<Lighting>().add(
//         &Lighting::azimuth, {.name = "azimuth", .minimum = 0.0, .maximum = 360.0, .units = "deg", .doc = "..."});
//     return bindings;
//   }
//   type.parameters = lightingParameters().declarations();        // in the node type's declaration
//   const Lighting lighting = lightingParameters().read(setup.parameters);   // in the node
template <class Settings>
class ParameterBindings {
 public:
  // A parameter with the default `Settings{}` gives the member. Declared `optional`, it has none: the
  // member keeps that value when the parameter is not given (an empty path: no file).
  template <class T>
  ParameterBindings& add(T Settings::*member, ParameterDeclaration declaration) {
    if (declaration.optional)
      declaration.defaultValue.reset();
    else
      declaration.defaultValue = ParameterTraits<T>::held(Settings{}.*member);
    return bindMember(member, std::move(declaration));
  }
  // A parameter a user must give: it has no default.
  template <class T>
  ParameterBindings& required(T Settings::*member, ParameterDeclaration declaration) {
    declaration.defaultValue.reset();
    return bindMember(member, std::move(declaration));
  }
  // A parameter a user may leave out, for the node to decide without it: the member stays empty.
  template <class T>
  ParameterBindings& add(std::optional<T> Settings::*member, ParameterDeclaration declaration) {
    declaration.type = ParameterTraits<T>::type(declaration);
    declaration.defaultValue.reset();
    declaration.optional = true;
    return bind(
        member, std::move(declaration),
        [member](Settings& settings, const ParameterValue& value) {
          settings.*member = ParameterTraits<T>::from(value);
        },
        [member](const Settings& settings) -> std::optional<ParameterValue> {
          if (!(settings.*member)) return std::nullopt;
          return ParameterTraits<T>::held(*(settings.*member));
        });
  }
  // A choice held as an enumeration: `names` spells each value as the pipeline writes it.
  template <class E>
  ParameterBindings& choice(E Settings::*member, ParameterDeclaration declaration,
                            std::vector<std::pair<std::string, E>> names) {
    declaration.type = ParameterType::Choice;
    declaration.choices.clear();
    for (const auto& entry : names) declaration.choices.push_back(entry.first);
    auto nameOf = [names](E value) -> ParameterValue {
      for (const auto& entry : names)
        if (entry.second == value) return entry.first;
      throw std::logic_error("a choice's value has no name");
    };
    declaration.defaultValue = nameOf(Settings{}.*member);
    return bind(
        member, std::move(declaration),
        [member, names](Settings& settings, const ParameterValue& value) {
          for (const auto& entry : names)
            if (entry.first == std::get<std::string>(value)) settings.*member = entry.second;
        },
        [member, nameOf](const Settings& settings) -> std::optional<ParameterValue> {
          return nameOf(settings.*member);
        });
  }
  // A parameter held in other units or another form than the pipeline writes it (MiB held as bytes):
  // `get` gives the value as written (and the default from Settings{}), `set` stores it.
  template <class T>
  ParameterBindings& convert(ParameterDeclaration declaration, std::function<T(const Settings&)> get,
                             std::function<void(Settings&, T)> set) {
    declaration.type = ParameterTraits<T>::type(declaration);
    declaration.defaultValue = ParameterTraits<T>::held(get(Settings{}));
    return bind(
        std::any(), std::move(declaration),
        [set](Settings& settings, const ParameterValue& value) { set(settings, ParameterTraits<T>::from(value)); },
        [get](const Settings& settings) -> std::optional<ParameterValue> {
          return ParameterTraits<T>::held(get(settings));
        });
  }

  const std::vector<ParameterDeclaration>& declarations() const { return declarations_; }

  // The settings a validated parameter set holds; what it lacks (an optional parameter) keeps its default.
  Settings read(const ParameterSet& parameters) const {
    Settings settings{};
    for (std::size_t i = 0; i < bindings_.size(); ++i)
      if (parameters.has(declarations_[i].name)) bindings_[i].set(settings, parameters.value(declarations_[i].name));
    return settings;
  }
  // The parameters that give `settings`, each placed at `where`: to show or change settings as parameters.
  ParameterSet parameters(const Settings& settings, const SourceLocation& where) const {
    ParameterSet parameters;
    for (std::size_t i = 0; i < bindings_.size(); ++i)
      if (std::optional<ParameterValue> value = bindings_[i].get(settings))
        parameters.set(declarations_[i].name, std::move(*value), where);
    return parameters;
  }
  // Where the value of the parameter held in `member` was written, for messages about it.
  template <class T>
  const SourceLocation& where(const ParameterSet& parameters, T Settings::*member) const {
    return parameters.where(declarationOf(member).name);
  }
  template <class T>
  const ParameterDeclaration& declarationOf(T Settings::*member) const {
    for (std::size_t i = 0; i < bindings_.size(); ++i)
      if (const auto* bound = std::any_cast<T Settings::*>(&bindings_[i].member); bound && *bound == member)
        return declarations_[i];
    throw std::logic_error("no parameter is bound to this member");
  }

 private:
  struct Binding {
    std::any member;  // the member pointer, for where(); empty for a converted parameter
    std::function<void(Settings&, const ParameterValue&)> set;
    std::function<std::optional<ParameterValue>(const Settings&)> get;
  };

  // An optional parameter whose member holds what it holds when not given has no value to show.
  template <class T>
  ParameterBindings& bindMember(T Settings::*member, ParameterDeclaration declaration) {
    declaration.type = ParameterTraits<T>::type(declaration);
    const bool optional = declaration.optional;
    return bind(
        member, std::move(declaration),
        [member](Settings& settings, const ParameterValue& value) {
          settings.*member = ParameterTraits<T>::from(value);
        },
        [member, optional](const Settings& settings) -> std::optional<ParameterValue> {
          if (optional && settings.*member == Settings{}.*member) return std::nullopt;
          return ParameterTraits<T>::held(settings.*member);
        });
  }

  ParameterBindings& bind(std::any member, ParameterDeclaration declaration,
                          std::function<void(Settings&, const ParameterValue&)> set,
                          std::function<std::optional<ParameterValue>(const Settings&)> get) {
    declarations_.push_back(std::move(declaration));
    bindings_.push_back({std::move(member), std::move(set), std::move(get)});
    return *this;
  }

  std::vector<ParameterDeclaration> declarations_;
  std::vector<Binding> bindings_;
};

}  // namespace strata
