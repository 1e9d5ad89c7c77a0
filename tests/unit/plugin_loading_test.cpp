// Plugin modules: the built-in ones load and register their types; modules built for another plugin ABI
// version, or without the entry point, are refused with a message that names the file and the fix.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include <strata/plugin/node.hpp>
#include <strata/plugin/plugin_registry.hpp>

namespace strata {
namespace {

namespace fs = std::filesystem;

std::string errorMessage(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& error) {
    return error.what();
  }
  return "(no error)";
}

NodeTypeDeclaration typeNamed(const std::string& name, const std::string& summary) {
  NodeTypeDeclaration type;
  type.type = name;
  type.summary = summary;
  type.output = PortType::Layer;
  type.create = [](const NodeSetup&) { return std::unique_ptr<Node>(); };
  return type;
}

TEST(PluginLoading, BuiltInModulesRegisterTheirTypes) {
  PluginRegistry registry;
  registry.loadDirectories({STRATA_TEST_PLUGIN_DIR});
  for (const char* type :
       {"source.gdal", "source.procedural", "geometry.icosahedral", "geometry.pgm", "geometry.healpix",
        "geometry.clipmap", "geometry.bdam", "output.image", "composite.projection_quality", "composite.overlay_mask",
        "composite.temporal_blend", "composite.relief", "composite.chroma_fusion", "composite.layer_peel",
        "composite.peeled_surface"})
    EXPECT_NE(registry.find(type), nullptr) << type;
  ASSERT_EQ(registry.modules().size(), 14u);
  EXPECT_EQ(registry.modules()[0].name, "composite-chroma-fusion");  // files load in name order
}

TEST(PluginLoading, BuiltInProjectionsAreRegisteredWithTheirProjNames) {
  PluginRegistry registry;
  for (const char* type : {"equirectangular", "polar-stereographic", "healpix", "orthographic", "perspective"})
    EXPECT_NE(registry.findProjection(type), nullptr) << type;
  ASSERT_NE(registry.projectionForProjName("stere"), nullptr);
  EXPECT_EQ(registry.projectionForProjName("stere")->type, "polar-stereographic");
  EXPECT_EQ(registry.projectionForProjName("merc"), nullptr);
}

TEST(PluginLoading, AnotherAbiVersionIsRefusedNamingBothVersions) {
  PluginRegistry registry;
  const std::string message = errorMessage([&] { registry.loadModule(STRATA_WRONG_ABI_PLUGIN); });
  EXPECT_NE(message.find(STRATA_WRONG_ABI_PLUGIN), std::string::npos) << message;
  EXPECT_NE(message.find("ABI version " + std::to_string(kPluginAbiVersion + 1)), std::string::npos) << message;
  EXPECT_NE(message.find("ABI version " + std::to_string(kPluginAbiVersion)), std::string::npos) << message;
  EXPECT_NE(message.find("rebuild the plugin"), std::string::npos) << message;
  EXPECT_TRUE(registry.modules().empty());
}

TEST(PluginLoading, ModuleWithoutEntryPointIsRefused) {
  PluginRegistry registry;
  const std::string message = errorMessage([&] { registry.loadModule(STRATA_NO_ENTRY_PLUGIN); });
  EXPECT_NE(message.find("not a Strata plugin"), std::string::npos) << message;
  EXPECT_NE(message.find("STRATA_PLUGIN("), std::string::npos) << message;
}

TEST(PluginLoading, FileThatIsNoSharedObjectIsRefused) {
  const fs::path file = fs::temp_directory_path() / "strata-not-a-library.so";
  std::ofstream(file) << "plain text";
  PluginRegistry registry;
  const std::string message = errorMessage([&] { registry.loadModule(file); });
  fs::remove(file);
  EXPECT_NE(message.find("cannot load plugin"), std::string::npos) << message;
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
}

TEST(PluginLoading, MissingDirectoriesAreSkipped) {
  PluginRegistry registry;
  registry.loadDirectories({"/nonexistent/strata/plugins", STRATA_TEST_PLUGIN_DIR});
  EXPECT_NE(registry.find("source.gdal"), nullptr);
}

// The test program's plugin directory beside it and the one beside libstrata_core are the same directory
// (build/lib/strata/plugins): it is searched once, and each module loads once.
TEST(PluginLoading, DefaultDirectoriesLoadEachModuleOnce) {
  PluginRegistry registry;
  registry.loadDirectories(defaultPluginDirectories());
  std::set<fs::path> files;
  for (const PluginRegistry::Module& module : registry.modules())
    EXPECT_TRUE(files.insert(fs::weakly_canonical(module.file)).second) << module.file << " loaded twice";
  EXPECT_NE(registry.find("source.gdal"), nullptr);
}

TEST(PluginRegistry, TheFirstRegistrationOfATypeWins) {
  PluginRegistry registry;
  registry.add(typeNamed("source.same", "first"));
  registry.add(typeNamed("source.same", "second"));
  ASSERT_NE(registry.find("source.same"), nullptr);
  EXPECT_EQ(registry.find("source.same")->summary, "first");
}

TEST(PluginRegistry, MalformedTypeNameIsRefused) {
  PluginRegistry registry;
  const std::string message = errorMessage([&] { registry.add(typeNamed("nodot", "")); });
  EXPECT_NE(message.find("category.name"), std::string::npos) << message;
}

}  // namespace
}  // namespace strata
