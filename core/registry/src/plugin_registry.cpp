#include <dlfcn.h>

#include <algorithm>

#include <strata/plugin/plugin_registry.hpp>

namespace strata {
namespace {

bool wellFormedTypeName(const std::string& type) {
  auto dot = type.find('.');
  return dot != std::string::npos && dot > 0 && dot + 1 < type.size();
}

}  // namespace

void PluginRegistry::add(NodeTypeDeclaration declaration) {
  SourceLocation where{loadingModule_.empty() ? std::string("(registered in code)") : loadingModule_};
  if (!wellFormedTypeName(declaration.type))
    throw Error(where, "node type '" + declaration.type + "' is not of the form category.name",
                "name node types like source.gdal or composite.relief");
  if (!declaration.create)
    throw Error(where, "node type '" + declaration.type + "' has no factory", "set NodeTypeDeclaration::create");
  if (types_.count(declaration.type)) return;  // an earlier directory's module provides it already
  std::string type = declaration.type;
  types_.emplace(std::move(type), std::move(declaration));
}

void PluginRegistry::loadModule(const std::filesystem::path& file) {
  SourceLocation where{file.string()};
  // RTLD_NOW finds unresolved symbols here, not in the middle of a frame. Modules are never closed:
  // nodes and their code must outlive every frame, and unloading C++ code is fragile.
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle)
    throw Error(where, std::string("cannot load plugin: ") + dlerror(),
                "rebuild the plugin against this Strata, or remove it from the plugin path");
  auto entry = reinterpret_cast<const StrataPluginInfo* (*)()>(dlsym(handle, STRATA_PLUGIN_ENTRY_SYMBOL));
  if (!entry)
    throw Error(where, "not a Strata plugin: it has no '" STRATA_PLUGIN_ENTRY_SYMBOL "' entry point",
                "define the entry point with STRATA_PLUGIN(name, version, registerFunction)");
  const StrataPluginInfo* info = entry();
  if (!info || info->abiVersion != kPluginAbiVersion)
    throw Error(where,
                "plugin built for plugin ABI version " + std::to_string(info ? info->abiVersion : -1) +
                    ", but this Strata " + kVersionString + " has ABI version " + std::to_string(kPluginAbiVersion),
                "rebuild the plugin against the installed Strata SDK");
  loadingModule_ = file.string();
  try {
    info->registerTypes(this);
  } catch (...) {
    loadingModule_.clear();
    throw;
  }
  loadingModule_.clear();
  modules_.push_back({file, info->name ? info->name : "", info->version ? info->version : ""});
}

void PluginRegistry::loadDirectories(const std::vector<std::filesystem::path>& directories) {
  for (const auto& directory : directories) {
    std::error_code error;
    if (!std::filesystem::is_directory(directory, error)) continue;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
      const std::string name = entry.path().filename().string();
      if (name.starts_with("strata-") && entry.path().extension() == ".so") files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());  // a stable order for "the first module wins"
    for (const auto& file : files) loadModule(file);
  }
}

const NodeTypeDeclaration* PluginRegistry::find(const std::string& type) const {
  auto found = types_.find(type);
  return found == types_.end() ? nullptr : &found->second;
}

std::vector<const NodeTypeDeclaration*> PluginRegistry::types() const {
  std::vector<const NodeTypeDeclaration*> all;
  for (const auto& [name, declaration] : types_) all.push_back(&declaration);
  return all;
}

}  // namespace strata
