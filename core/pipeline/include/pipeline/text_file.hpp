#pragma once
#include <filesystem>
#include <string>

#include <yaml-cpp/yaml.h>

namespace strata::loader {

// The whole of `file` as text, for the loaders of pipelines and camera paths. Throws strata::Error at the
// file when it is missing, a directory or unreadable, calling it a `what` file ("pipeline", "camera path")
// and, when it is missing, saying where `samples` are.
std::string readTextFile(const std::filesystem::path& file, const std::string& what, const std::string& samples);

// `text`, read from `file`, as YAML. Throws strata::Error at the line and column of a syntax error.
YAML::Node parseYamlText(const std::string& text, const std::string& file);

}  // namespace strata::loader
