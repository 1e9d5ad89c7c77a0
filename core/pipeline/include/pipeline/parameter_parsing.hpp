#pragma once
#include <filesystem>

#include <yaml-cpp/yaml.h>

#include <strata/plugin/parameter.hpp>

#include "pipeline/value_reading.hpp"

namespace strata::loader {

// Reads one parameter's YAML value against its declaration. Beyond the type (see value_reading.hpp):
//  - Integer and Real values, and each RealList element, must lie in [minimum, maximum] ((minimum, maximum]
//    when exclusiveMinimum);
//  - Real also takes integers; the value is stored as a double;
//  - RealList must have exactly `count` elements when count > 0;
//  - Choice must be one of `choices` (exact spelling);
//  - Path is resolved against `baseDirectory` when relative, stored absolute and normalised, and must
//    name something that exists.
// Throws strata::Error at the value; `context.label` names the parameter.
ParameterValue parseParameter(const YAML::Node& value, const ParameterDeclaration& declaration,
                              const ValueContext& context, const std::filesystem::path& baseDirectory);

// The declared default, with an integer default of a Real parameter made a double, so that nodes can
// read it with ParameterSet::real() (a plugin writing `defaultValue = 1` gets an int64_t).
ParameterValue defaultValue(const ParameterDeclaration& declaration);

}  // namespace strata::loader
