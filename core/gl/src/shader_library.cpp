#include <set>
#include <sstream>
#include <stdexcept>

#include <strata/gl/shader_library.hpp>
#include <strata/plugin/plugin_registry.hpp>

namespace strata {
namespace detail {
const std::map<std::string, std::string>& builtinShaderSources();  // generated from shaders/strata/
}

ShaderLibrary::ShaderLibrary() : sources_(detail::builtinShaderSources()) {}

void ShaderLibrary::add(const std::string& name, std::string source) { sources_[name] = std::move(source); }

void ShaderLibrary::addPluginSources(const PluginRegistry& registry) {
  for (const NodeTypeDeclaration* type : registry.types())
    for (const auto& [name, source] : type->shaderSources) add(name, source);
  for (const ProjectionDeclaration* projection : registry.projections())
    for (const auto& [name, source] : projection->shaderSources) add(name, source);
}

bool ShaderLibrary::has(const std::string& name) const { return sources_.count(name) != 0; }

const std::string& ShaderLibrary::source(const std::string& name) const {
  auto found = sources_.find(name);
  if (found == sources_.end()) throw std::out_of_range("no GLSL source named '" + name + "' in the shader library");
  return found->second;
}

std::string ShaderLibrary::expand(const std::string& name,
                                  const std::map<std::string, std::string>& substitutions) const {
  std::string text = source(name);
  for (const auto& [token, replacement] : substitutions)
    for (auto at = text.find(token); at != std::string::npos; at = text.find(token, at + replacement.size()))
      text.replace(at, token.size(), replacement);
  return expandText(text, name);
}

namespace {

// The quoted name of an `#include "name"` line, or empty.
std::string includedName(const std::string& line) {
  auto start = line.find_first_not_of(" \t");
  if (start == std::string::npos || line.compare(start, 8, "#include") != 0) return {};
  auto open = line.find('"', start + 8);
  auto close = open == std::string::npos ? open : line.find('"', open + 1);
  if (close == std::string::npos) throw std::runtime_error("malformed GLSL include: " + line);
  return line.substr(open + 1, close - open - 1);
}

void expandInto(const ShaderLibrary& library, const std::string& text, const std::string& origin,
                std::set<std::string>& included, std::ostringstream& out) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::string name = includedName(line);
    if (name.empty()) {
      out << line << '\n';
      continue;
    }
    if (!library.has(name)) throw std::runtime_error(origin + ": includes unknown GLSL source '" + name + "'");
    if (!included.insert(name).second) continue;  // each snippet once per program
    out << "// begin " << name << '\n';
    expandInto(library, library.source(name), name, included, out);
    out << "// end " << name << '\n';
  }
}

}  // namespace

std::string ShaderLibrary::expandText(const std::string& text, const std::string& origin) const {
  std::set<std::string> included;
  std::ostringstream out;
  expandInto(*this, text, origin, included, out);
  return out.str();
}

}  // namespace strata
