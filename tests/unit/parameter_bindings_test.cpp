// ParameterBindings (strata/plugin/parameter_bindings.hpp): a settings struct's members declared once as
// parameters, read back typed, with their defaults from the struct and their locations for messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <strata/plugin/parameter_bindings.hpp>

namespace strata::testing {
namespace {

enum class Edge { Hard, Feathered };

struct Settings {
  double width = 2.5;
  int count = 3;
  bool enabled = true;
  std::string label = "grid";
  std::filesystem::path file;
  std::vector<double> colour{1.0, 0.5, 0.0};
  Edge edge = Edge::Feathered;
  std::optional<double> highest;
  std::int64_t bytes = 4 << 20;
};

const ParameterBindings<Settings>& bindings() {
  static const auto bound =
      ParameterBindings<Settings>()
          .add(&Settings::width, {.name = "width", .minimum = 0.0, .units = "m", .doc = "how wide"})
          .add(&Settings::count, {.name = "count"})
          .add(&Settings::enabled, {.name = "enabled", .live = true})
          .add(&Settings::label, {.name = "label"})
          .required(&Settings::file, {.name = "file"})
          .add(&Settings::colour, {.name = "colour", .count = 3})
          .choice(&Settings::edge, {.name = "edge"}, {{"hard", Edge::Hard}, {"feathered", Edge::Feathered}})
          .add(&Settings::highest, {.name = "highest", .units = "m"})
          .convert<std::int64_t>(
              {.name = "mebibytes"}, [](const Settings& s) { return s.bytes >> 20; },
              [](Settings& s, std::int64_t mib) { s.bytes = mib << 20; });
  return bound;
}

const ParameterDeclaration& declared(const std::string& name) {
  for (const ParameterDeclaration& declaration : bindings().declarations())
    if (declaration.name == name) return declaration;
  throw std::logic_error("no parameter " + name);
}

TEST(ParameterBindings, TypesAndDefaultsComeFromTheMembers) {
  EXPECT_EQ(declared("width").type, ParameterType::Real);
  EXPECT_EQ(std::get<double>(*declared("width").defaultValue), 2.5);
  EXPECT_EQ(declared("width").units, "m");
  EXPECT_EQ(declared("count").type, ParameterType::Integer);
  EXPECT_EQ(std::get<std::int64_t>(*declared("count").defaultValue), 3);
  EXPECT_EQ(declared("enabled").type, ParameterType::Boolean);
  EXPECT_TRUE(declared("enabled").live);
  EXPECT_EQ(declared("label").type, ParameterType::String);
  EXPECT_EQ(declared("file").type, ParameterType::Path);
  EXPECT_FALSE(declared("file").defaultValue) << "required";
  EXPECT_FALSE(declared("file").optional);
  EXPECT_EQ(declared("colour").type, ParameterType::RealList);
  EXPECT_EQ(std::get<std::vector<double>>(*declared("colour").defaultValue), (std::vector<double>{1.0, 0.5, 0.0}));
  EXPECT_EQ(declared("edge").type, ParameterType::Choice);
  EXPECT_EQ(declared("edge").choices, (std::vector<std::string>{"hard", "feathered"}));
  EXPECT_EQ(std::get<std::string>(*declared("edge").defaultValue), "feathered");
  EXPECT_TRUE(declared("highest").optional);
  EXPECT_FALSE(declared("highest").defaultValue);
  EXPECT_EQ(std::get<std::int64_t>(*declared("mebibytes").defaultValue), 4);
}

TEST(ParameterBindings, ReadsASetTypedAndKeepsDefaultsForWhatItLacks) {
  ParameterSet set;
  set.set("width", 7.0, {"p.yaml", 3, 12});
  set.set("file", std::string("/data/a.tif"), {"p.yaml", 4, 9});
  set.set("edge", std::string("hard"), {});
  set.set("highest", 8848.0, {});
  set.set("mebibytes", std::int64_t(64), {});
  const Settings settings = bindings().read(set);
  EXPECT_EQ(settings.width, 7.0);
  EXPECT_EQ(settings.count, 3);
  EXPECT_EQ(settings.file, std::filesystem::path("/data/a.tif"));
  EXPECT_EQ(settings.edge, Edge::Hard);
  EXPECT_EQ(settings.highest, 8848.0);
  EXPECT_EQ(settings.bytes, std::int64_t(64) << 20);
  EXPECT_EQ(bindings().where(set, &Settings::width).line, 3);
  EXPECT_EQ(bindings().where(set, &Settings::file).column, 9);
}

TEST(ParameterBindings, WritesSettingsBackAsTheParametersThatGiveThem) {
  Settings settings;
  settings.edge = Edge::Hard;
  const ParameterSet set = bindings().parameters(settings, {"viewer"});
  EXPECT_EQ(std::get<std::string>(set.value("edge")), "hard");
  EXPECT_EQ(std::get<std::int64_t>(set.value("mebibytes")), 4);
  EXPECT_FALSE(set.has("highest")) << "an optional parameter left empty has no value";
  EXPECT_EQ(set.where("width").file, "viewer");
  const Settings again = bindings().read(set);
  EXPECT_EQ(again.edge, Edge::Hard);
  EXPECT_EQ(again.colour, settings.colour);
}

TEST(ParameterBindings, AMemberBoundToNoParameterIsABugInTheNode) {
  struct Other {
    double bound = 0.0, unbound = 0.0;
  };
  const auto other = ParameterBindings<Other>().add(&Other::bound, {.name = "bound"});
  EXPECT_EQ(other.declarationOf(&Other::bound).name, "bound");
  EXPECT_THROW(other.declarationOf(&Other::unbound), std::logic_error);
}

}  // namespace
}  // namespace strata::testing
