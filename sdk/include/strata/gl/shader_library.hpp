#pragma once
#include <map>
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

// Named GLSL sources. The built-in ones come from shaders/ (embedded at build time); plugins may add
// their own. A line `#include "name"` is replaced by that source, once per program.
class ShaderLibrary {
 public:
  ShaderLibrary();  // holds the built-in sources

  void add(const std::string& name, std::string source);
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
