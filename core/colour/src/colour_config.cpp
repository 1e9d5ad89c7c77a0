#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <strata/colour_config.hpp>

#include "builtin_ocio_config.hpp"

namespace strata {
namespace OCIO = OCIO_NAMESPACE;

struct ColourConfig::Impl {
  OCIO::ConstConfigRcPtr config;
};

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "'" : ", '") + name + "'";
  return text;
}

// OCIO's GLSL for `processor`, as `vec4 functionName(vec4)`; refused where it needs textures (LUTs).
std::string glslOf(const OCIO::ConstProcessorRcPtr& processor, const std::string& functionName, const std::string& what,
                   const SourceLocation& where) {
  OCIO::GpuShaderDescRcPtr shader = OCIO::GpuShaderDesc::CreateShaderDesc();
  shader->setLanguage(OCIO::GPU_LANGUAGE_GLSL_4_0);
  shader->setFunctionName(functionName.c_str());
  shader->setResourcePrefix((functionName + "_").c_str());
  processor->getDefaultGPUProcessor()->extractGpuShaderInfo(shader);
  if (shader->getNumTextures() > 0 || shader->getNum3DTextures() > 0 || shader->getNumUniforms() > 0)
    throw Error(where, what + " needs lookup tables or uniforms on the GPU, which Strata does not bind yet",
                "use a colour space defined by closed-form transforms (exponents, matrices, log curves)");
  return shader->getShaderText();
}

}  // namespace

ColourConfig::ColourConfig(std::shared_ptr<const Impl> impl, std::string origin)
    : impl_(std::move(impl)), origin_(std::move(origin)) {}

ColourConfig ColourConfig::load(const std::filesystem::path& file, const SourceLocation& where) {
  const char* environment = std::getenv("OCIO");
  const std::filesystem::path chosen = !file.empty() ? file : environment && *environment ? environment : "";
  std::error_code error;
  if (!chosen.empty() && std::filesystem::is_directory(chosen, error))
    throw Error(where, "'" + chosen.string() + "' is a folder, not an OpenColorIO config",
                "give the config file in it, e.g. " + (chosen / "config.ocio").string());
  try {
    auto impl = std::make_shared<Impl>();
    if (chosen.empty()) {
      std::istringstream text{std::string(kBuiltinOcioConfig)};
      impl->config = OCIO::Config::CreateFromStream(text);
    } else {
      impl->config = OCIO::Config::CreateFromFile(chosen.c_str());
    }
    impl->config->validate();
    return ColourConfig(std::move(impl), chosen.empty() ? "Strata's built-in config" : chosen.string());
  } catch (const OCIO::Exception& exception) {
    throw Error(where,
                "OpenColorIO cannot use the config " + (chosen.empty() ? "built in" : "'" + chosen.string() + "'") +
                    (file.empty() && !chosen.empty() ? " ($OCIO)" : "") + ": " + exception.what(),
                "check the config with `ociocheck --iconfig FILE`, or unset OCIO to use Strata's own");
  }
}

std::vector<std::string> ColourConfig::colourSpaces() const {
  std::vector<std::string> names;
  for (int i = 0; i < impl_->config->getNumColorSpaces(); ++i)
    names.emplace_back(impl_->config->getColorSpaceNameByIndex(i));
  return names;
}

std::string ColourConfig::defaultDisplay() const { return impl_->config->getDefaultDisplay(); }

std::string ColourConfig::defaultView(const std::string& display) const {
  return impl_->config->getDefaultView(display.c_str());
}

void ColourConfig::requireColourSpace(const std::string& space, const SourceLocation& where) const {
  if (!impl_->config->getColorSpace(space.c_str()))
    throw Error(where, "the colour space '" + space + "' is not in " + origin_,
                "choose one of " + joined(colourSpaces()));
}

std::string ColourConfig::toSceneLinear(const std::string& space, const std::string& functionName,
                                        const SourceLocation& where) const {
  requireColourSpace(space, where);
  return glslOf(impl_->config->getProcessor(space.c_str(), OCIO::ROLE_SCENE_LINEAR), functionName,
                "the conversion from '" + space + "'", where);
}

bool ColourConfig::isSceneLinear(const std::string& space, const SourceLocation& where) const {
  requireColourSpace(space, where);
  return impl_->config->getProcessor(space.c_str(), OCIO::ROLE_SCENE_LINEAR)->isNoOp();
}

std::string ColourConfig::toDisplay(const std::string& display, const std::string& view,
                                    const std::string& functionName, const SourceLocation& where) const {
  std::vector<std::string> displays, views;
  for (int i = 0; i < impl_->config->getNumDisplays(); ++i) displays.emplace_back(impl_->config->getDisplay(i));
  if (std::find(displays.begin(), displays.end(), display) == displays.end())
    throw Error(where, "the display '" + display + "' is not in " + origin_, "choose one of " + joined(displays));
  for (int i = 0; i < impl_->config->getNumViews(display.c_str()); ++i)
    views.emplace_back(impl_->config->getView(display.c_str(), i));
  if (std::find(views.begin(), views.end(), view) == views.end())
    throw Error(where, "the display '" + display + "' has no view '" + view + "' in " + origin_,
                "choose one of " + joined(views));
  return glslOf(impl_->config->getProcessor(impl_->config->getCurrentContext(), OCIO::ROLE_SCENE_LINEAR,
                                            display.c_str(), view.c_str(), OCIO::TRANSFORM_DIR_FORWARD),
                functionName, "the display '" + display + "' view '" + view + "'", where);
}

}  // namespace strata
