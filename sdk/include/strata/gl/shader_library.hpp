#pragma once
#include <map>
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

class PluginRegistry;

// Named GLSL sources. The SDK's shared library comes from shaders/strata/ (embedded at build time);
// plugins add their own through their node type and projection declarations. A line `#include "name"`
// is replaced by that source, once per program.
class ShaderLibrary {
 public:
  ShaderLibrary();  // holds the SDK's sources

  void add(const std::string& name, std::string source);
  // Adds the GLSL every node type and projection of `registry` declares (NodeTypeDeclaration::shaderSources,
  // ProjectionDeclaration::shaderSources).
  void addPluginSources(const PluginRegistry& registry);
  bool has(const std::string& name) const;
  const std::string& source(const std::string& name) const;  // throws std::out_of_range naming it
  // The source named `name`, with each placeholder token of `substitutions` replaced by its text (e.g. a
  // layer's GLSL pasted where a program samples it), then its includes expanded.
  std::string expand(const std::string& name, const std::map<std::string, std::string>& substitutions = {}) const;
  std::string expandText(const std::string& text, const std::string& origin) const;

 private:
  std::map<std::string, std::string> sources_;
};

}  // namespace strata
STRATA_EXPORTS_END
