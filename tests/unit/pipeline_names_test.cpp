#include <gtest/gtest.h>

#include <strata/plugin/node_type.hpp>

namespace strata {
namespace {

TEST(NamesTest, LayerKindsReadBackFromTheirNames) {
  for (LayerKind kind : {LayerKind::Height, LayerKind::Color, LayerKind::Luminance, LayerKind::Chroma,
                         LayerKind::Normal, LayerKind::Mask, LayerKind::Scalar}) {
    LayerKind parsed = LayerKind::Color;
    ASSERT_TRUE(parseLayerKind(toString(kind), parsed)) << toString(kind);
    EXPECT_EQ(parsed, kind);
  }
  EXPECT_STREQ(toString(LayerKind::Height), "height");
  EXPECT_STREQ(toString(LayerKind::Color), "color");
}

TEST(NamesTest, UnknownLayerKindIsRefusedAndLeavesTheKind) {
  LayerKind kind = LayerKind::Mask;
  EXPECT_FALSE(parseLayerKind("colour", kind));
  EXPECT_FALSE(parseLayerKind("Height", kind));
  EXPECT_EQ(kind, LayerKind::Mask);
}

TEST(NamesTest, PortParameterAndCategoryNames) {
  EXPECT_STREQ(toString(PortType::Layer), "layer");
  EXPECT_STREQ(toString(PortType::Geometry), "geometry");
  EXPECT_STREQ(toString(ParameterType::Boolean), "boolean");
  EXPECT_STREQ(toString(ParameterType::Integer), "integer");
  EXPECT_STREQ(toString(ParameterType::Real), "real");
  EXPECT_STREQ(toString(ParameterType::String), "string");
  EXPECT_STREQ(toString(ParameterType::Path), "path");
  EXPECT_STREQ(toString(ParameterType::Choice), "choice");
  EXPECT_STREQ(toString(ParameterType::RealList), "real list");
  EXPECT_STREQ(toString(NodeCategory::Source), "source");
  EXPECT_STREQ(toString(NodeCategory::Compositor), "compositor");
  EXPECT_STREQ(toString(NodeCategory::Geometry), "geometry");
  EXPECT_STREQ(toString(NodeCategory::Output), "output");
}

TEST(NodeTypeDeclarationTest, FindsInputsAndParametersByName) {
  NodeTypeDeclaration declaration;
  declaration.inputs = {PortDeclaration{"geometry", PortType::Geometry, {}, false, false, ""},
                        PortDeclaration{"surface", PortType::Layer, {}, true, false, ""}};
  ParameterDeclaration scale;
  scale.name = "scale";
  declaration.parameters = {scale};

  ASSERT_NE(declaration.findInput("surface"), nullptr);
  EXPECT_TRUE(declaration.findInput("surface")->list);
  EXPECT_EQ(declaration.findInput("scale"), nullptr);
  ASSERT_NE(declaration.findParameter("scale"), nullptr);
  EXPECT_EQ(declaration.findParameter("scale")->name, "scale");
  EXPECT_EQ(declaration.findParameter("surface"), nullptr);
}

}  // namespace
}  // namespace strata
