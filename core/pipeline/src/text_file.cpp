#include "pipeline/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <strata/error.hpp>

namespace strata::loader {

std::string readTextFile(const std::filesystem::path& file, const std::string& what, const std::string& samples) {
  const SourceLocation where{file.string()};
  std::error_code error;
  if (!std::filesystem::exists(file, error)) throw Error(where, what + " file not found", "check the path; " + samples);
  if (std::filesystem::is_directory(file, error))
    throw Error(where, "this is a directory, not a " + what + " file", "give the path of a " + what + " .yaml file");
  std::ifstream stream(file, std::ios::binary);
  if (!stream)
    throw Error(where, "cannot read the " + what + " file: " + std::strerror(errno), "check the file's permissions");
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

YAML::Node parseYamlText(const std::string& text, const std::string& file) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& exception) {
    // yaml-cpp counts from 0; an exception without a mark has -1, which becomes "no line".
    throw Error(SourceLocation{file, exception.mark.line + 1, exception.mark.column + 1},
                "invalid YAML: " + exception.msg,
                "correct the YAML near this line and column (check indentation, ':' after keys and closing brackets)");
  }
}

}  // namespace strata::loader
