// The body:, camera:, date:, sun:, atmosphere: and colour: sections.
#include "pipeline_test_fixtures.hpp"

#include <strata/log.hpp>

namespace strata::testing {
namespace {

class SceneTest : public PipelineTest {
 protected:
  // `section` is line 2 of the pipeline; the nodes follow it.
  std::string withSection(const std::string& section) const {
    return "strata: 1\n" + section + "\nnodes:\n" + kFrameNodes;
  }
};

TEST_F(SceneTest, CameraKeysAreAllOptional) {
  const Camera camera = parse(withSection("camera: {altitude: 5000, tilt: 60}")).camera;
  EXPECT_DOUBLE_EQ(camera.altitude, 5000.0);
  EXPECT_DOUBLE_EQ(camera.tilt, 60.0);
  EXPECT_DOUBLE_EQ(camera.lon, Camera{}.lon);
  EXPECT_DOUBLE_EQ(camera.fov, Camera{}.fov);
}

TEST_F(SceneTest, LongitudeWrapsIntoMinus180To180) {
  EXPECT_DOUBLE_EQ(parse(withSection("camera: {lon: 190}")).camera.lon, -170.0);
  EXPECT_DOUBLE_EQ(parse(withSection("camera: {lon: 180}")).camera.lon, -180.0);
  EXPECT_DOUBLE_EQ(parse(withSection("camera: {lon: -180}")).camera.lon, -180.0);
  EXPECT_DOUBLE_EQ(parse(withSection("camera: {lon: -190}")).camera.lon, 170.0);
  EXPECT_DOUBLE_EQ(parse(withSection("camera: {lon: 725.5}")).camera.lon, 5.5);
  EXPECT_DOUBLE_EQ(parse(withSection("camera: {lon: 179.5}")).camera.lon, 179.5);
}

TEST_F(SceneTest, BoundsThemselvesAreAllowedWhereInclusive) {
  const Camera camera = parse(withSection("camera: {lat: -90, tilt: 90, heading: 400}")).camera;
  EXPECT_DOUBLE_EQ(camera.lat, -90.0);
  EXPECT_DOUBLE_EQ(camera.tilt, 90.0);
  EXPECT_DOUBLE_EQ(camera.heading, 400.0);  // kept as given
}

TEST_F(SceneTest, CameraValueThatIsNotANumber) {
  const Error error = parseError(withSection("camera: {lon: 10, altitude: high}"));
  EXPECT_EQ(error.problem(), "camera 'altitude' expects a number, got 'high'");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 29);
  EXPECT_FALSE(error.fix().empty());
}

TEST_F(SceneTest, QuotedNumberIsText) {
  const Error error = parseError(withSection("camera: {fov: \"30\"}"));
  EXPECT_EQ(error.problem(), "camera 'fov' expects a number, got quoted text \"30\"");
  EXPECT_NE(error.fix().find("without quotes"), std::string::npos);
}

TEST_F(SceneTest, InfinityIsNotANumberHere) {
  const Error error = parseError(withSection("camera: {altitude: .inf}"));
  EXPECT_EQ(error.problem(), "camera 'altitude' expects a number, got '.inf'");
}

TEST_F(SceneTest, DateIsOptionalAndReadAsIso8601) {
  EXPECT_FALSE(parse(withSection("camera: {}")).date);
  EXPECT_DOUBLE_EQ(*parse(withSection("date: 2004-06-15")).date, 1627.0);  // 1461 days to 2004, 166 into it
  EXPECT_DOUBLE_EQ(*parse(withSection("date: 2000-01-01T18:00Z")).date, 0.75);
}

TEST_F(SceneTest, DateThatIsNoDay) {
  const Error error = parseError(withSection("date: 2004-02-30"));
  EXPECT_EQ(error.problem(), "the scene's 'date' is '2004-02-30', which is not a date");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 7);
  EXPECT_NE(error.fix().find("ISO 8601"), std::string::npos);
}

TEST_F(SceneTest, ColourConfigIsAFileBesideThePipeline) {
  EXPECT_TRUE(parse(withSection("camera: {}")).colour.config.empty());
  directory_.write("wall.ocio", "ocio_profile_version: 2\n");
  const ColourSettings colour = parse(withSection("colour: {config: wall.ocio}")).colour;
  EXPECT_EQ(colour.config, directory_.path() / "wall.ocio");
  EXPECT_EQ(colour.where.line, 2);
  const Error error = parseError(withSection("colour: {config: missing.ocio}"));
  EXPECT_EQ(error.problem(), "colour 'config': file not found: " + (directory_.path() / "missing.ocio").string());
  EXPECT_EQ(error.where().column, 18);
  EXPECT_NE(parseError(withSection("colour: {confg: wall.ocio}")).problem().find("did you mean 'config'"),
            std::string::npos);
}

TEST_F(SceneTest, LatitudeOutOfRange) {
  const Error error = parseError(withSection("camera: {lat: 95}"));
  EXPECT_EQ(error.problem(), "camera 'lat' must be in [-90, 90] deg, got 95 deg");
  EXPECT_EQ(error.fix(), "choose a value in [-90, 90] deg");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 15);
}

TEST_F(SceneTest, AltitudeMustBeAboveZero) {
  const Error error = parseError(withSection("camera: {altitude: 0}"));
  EXPECT_EQ(error.problem(), "camera 'altitude' must be > 0 m, got 0 m");
}

TEST_F(SceneTest, TiltOutOfRange) {
  const Error error = parseError(withSection("camera: {tilt: -5}"));
  EXPECT_EQ(error.problem(), "camera 'tilt' must be in [0, 90] deg, got -5 deg");
}

// Issue 37, item 7: a field of view of 1e-8 degrees drew a torn surface and 1e-320 nothing at all.
TEST_F(SceneTest, FieldOfViewKeepsWithinWhatFloatDraws) {
  EXPECT_EQ(parseError(withSection("camera: {fov: 180}")).problem(),
            "camera 'fov' must be in [0.001, 179] deg, got 180 deg");
  EXPECT_EQ(parseError(withSection("camera: {fov: 0}")).problem(),
            "camera 'fov' must be in [0.001, 179] deg, got 0 deg");
  EXPECT_EQ(parseError(withSection("camera: {fov: 1e-8}")).problem(),
            "camera 'fov' must be in [0.001, 179] deg, got 1e-8 deg");
  EXPECT_EQ(parseError(withSection("camera: {fov: 1e-320}")).problem(),
            "camera 'fov' must be in [0.001, 179] deg, got 1e-320 deg");
  EXPECT_DOUBLE_EQ(parse(withSection("camera: {fov: 179}")).camera.fov, 179.0);
  EXPECT_DOUBLE_EQ(parse(withSection("camera: {fov: 0.001}")).camera.fov, 0.001);
}

TEST_F(SceneTest, UnknownCameraKeySuggestsTheNearest) {
  const Error error = parseError(withSection("camera: {altitude: 5000, tlit: 30}"));
  EXPECT_EQ(error.problem(), "unknown key 'tlit' in camera; did you mean 'tilt'?");
  EXPECT_EQ(error.fix(), "the keys of camera are 'lon', 'lat', 'altitude', 'heading', 'tilt', 'fov', 'body'");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 26);
}

TEST_F(SceneTest, CameraThatIsNotAMap) {
  const Error error = parseError(withSection("camera: 20000"));
  EXPECT_EQ(error.problem(), "'camera' must be a map, got '20000'");
  EXPECT_NE(error.fix().find("camera: {"), std::string::npos);
  EXPECT_EQ(error.where().column, 9);
}

TEST_F(SceneTest, RepeatedCameraKey) {
  const Error error = parseError(withSection("camera: {fov: 30, fov: 60}"));
  EXPECT_NE(error.problem().find("key 'fov' appears twice"), std::string::npos) << error.what();
  EXPECT_EQ(error.where().column, 19);
}

TEST_F(SceneTest, BodyNameAndRadius) {
  const Body body = parse(withSection("body: {name: Moon, radius: 1737400}")).body;
  EXPECT_EQ(body.name, "Moon");
  EXPECT_DOUBLE_EQ(body.radius, 1737400.0);
}

// A named body takes the IAU report's mean radius (strata/named_bodies.hpp); a radius given wins.
TEST_F(SceneTest, NamedBodyTakesItsMeanRadius) {
  EXPECT_DOUBLE_EQ(parse(withSection("body: {name: Mars}")).body.radius, 3389500.0);
  EXPECT_DOUBLE_EQ(parse(withSection("body: {name: moon}")).body.radius, 1737400.0);
  EXPECT_DOUBLE_EQ(parse(withSection("body: {name: Mars, radius: 3396190}")).body.radius, 3396190.0);
  EXPECT_DOUBLE_EQ(parse(withSection("camera: {}")).body.radius, Body{}.radius);
}

TEST_F(SceneTest, UnknownBodyWithoutARadius) {
  const Error error = parseError(withSection("body: {name: Vulcan}"));
  EXPECT_EQ(error.problem(), "'Vulcan' is not a body Strata knows by name, and no radius is given");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_NE(error.fix().find("radius"), std::string::npos);
  EXPECT_NE(error.fix().find("Ganymede"), std::string::npos);
  EXPECT_DOUBLE_EQ(parse(withSection("body: {name: Vulcan, radius: 500000}")).body.radius, 500000.0);
}

TEST_F(SceneTest, RadiusInKilometresIsRefused) {
  const Error named = parseError(withSection("body: {name: Mars, radius: 3389.5}"));
  EXPECT_EQ(named.problem(), "body radius 3389.5 looks like kilometres: Mars's mean radius is 3389500 m");
  EXPECT_EQ(named.where().column, 28);
  EXPECT_NE(named.fix().find("metres"), std::string::npos);
  // Unnamed, it is taken for the body whose radius it would be in kilometres.
  EXPECT_EQ(parseError(withSection("body: {radius: 6371}")).problem(),
            "body radius 6371 looks like kilometres: Earth's mean radius is 6371000 m");
  // A small body of its own name may be that small.
  EXPECT_DOUBLE_EQ(parse(withSection("body: {name: Bennu, radius: 3389.5}")).body.radius, 3389.5);
}

TEST_F(SceneTest, NamedBodyGivenAnotherRadiusIsWarnedAndDrawnSo) {
  std::vector<LogMessage> warnings;
  const LogSink previous = setLogSink([&warnings](const LogMessage& message) { warnings.push_back(message); });
  const Body body = parse(withSection("body: {name: Mars, radius: 6371000}")).body;
  setLogSink(previous);
  EXPECT_DOUBLE_EQ(body.radius, 6371000.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].text.find("is not Mars's (mean 3389500 m)"), std::string::npos) << warnings[0].text;
  EXPECT_NE(warnings[0].text.find(":2:"), std::string::npos) << warnings[0].text;
}

TEST_F(SceneTest, SunIsAFixedSubsolarPoint) {
  const Pipeline pipeline = parse(withSection("sun: {lon: 190, lat: -20}"));
  ASSERT_TRUE(pipeline.sun);
  EXPECT_DOUBLE_EQ(pipeline.sun->lon, -170.0);
  EXPECT_DOUBLE_EQ(pipeline.sun->lat, -20.0);
  EXPECT_FALSE(parse(withSection("camera: {}")).sun);
  EXPECT_EQ(parseError(withSection("sun: {lat: 95}")).problem(), "sun 'lat' must be in [-90, 90] deg, got 95 deg");
}

// `atmosphere: {}` is the Earth's air [Bruneton 2008]; each coefficient may be given, the three channels' as a
// list; none without the section.
TEST_F(SceneTest, AtmosphereDefaultsToTheEarthsAir) {
  const Pipeline pipeline = parse(withSection("atmosphere: {}"));
  ASSERT_TRUE(pipeline.atmosphere);
  EXPECT_EQ(pipeline.atmosphere->rayleighScattering, glm::dvec3(5.8e-6, 13.5e-6, 33.1e-6));
  EXPECT_DOUBLE_EQ(pipeline.atmosphere->mieScaleHeight, 1200.0);
  EXPECT_EQ(pipeline.atmosphere->where.line, 2);
  const Pipeline hazy =
      parse(withSection("atmosphere: {rayleigh_scattering: [1.0e-5, 2.0e-5, 3.0e-5], thickness: 1.0e5}"));
  EXPECT_EQ(hazy.atmosphere->rayleighScattering, glm::dvec3(1.0e-5, 2.0e-5, 3.0e-5));
  EXPECT_DOUBLE_EQ(hazy.atmosphere->thickness, 1.0e5);
  EXPECT_FALSE(parse(withSection("camera: {}")).atmosphere);
}

// Aerosols scatter part of what they take from the light: extinction below scattering is refused with the fix.
TEST_F(SceneTest, AtmosphereExtinctionIsAtLeastItsScattering) {
  const Error error = parseError(withSection("atmosphere: {mie_scattering: 2.0e-5, mie_extinction: 1.0e-5}"));
  EXPECT_NE(error.problem().find("less than their scattering"), std::string::npos) << error.problem();
  EXPECT_NE(error.fix().find("mie_scattering / 0.9"), std::string::npos) << error.fix();
  EXPECT_EQ(error.where().line, 2);
  EXPECT_NE(parseError(withSection("atmosphere: {thickness: 0}")).problem().find("thickness"), std::string::npos);
}

// Issue 37, item 7: a body of 1e14 m was drawn speckled and of 1e20 m grey.
TEST_F(SceneTest, BodyRadiusKeepsWithinWhatFloatDraws) {
  const Error error = parseError(withSection("body: {name: Moon, radius: -1}"));
  EXPECT_EQ(error.problem(), "body 'radius' must be in [1, 1e+09] m, got -1 m");
  EXPECT_EQ(error.where().line, 2);
  EXPECT_EQ(error.where().column, 28);
  EXPECT_EQ(parseError(withSection("body: {radius: 1e14}")).problem(),
            "body 'radius' must be in [1, 1e+09] m, got 1e14 m");
  EXPECT_DOUBLE_EQ(parse(withSection("body: {name: Sun, radius: 6.957e8}")).body.radius, 6.957e8);
}

TEST_F(SceneTest, BodyRadiusThatIsNotANumber) {
  const Error error = parseError(withSection("body: {radius: [1, 2]}"));
  EXPECT_EQ(error.problem(), "body 'radius' expects a number, got a list");
}

TEST_F(SceneTest, UnknownBodyKeySuggestsTheNearest) {
  const Error error = parseError(withSection("body: {nmae: Mars}"));
  EXPECT_EQ(error.problem(), "unknown key 'nmae' in body; did you mean 'name'?");
  EXPECT_EQ(error.where().column, 8);
}

TEST_F(SceneTest, BodyNameMustBeText) {
  const Error error = parseError(withSection("body: {name: {planet: Mars}}"));
  EXPECT_EQ(error.problem(), "body 'name' expects text, got a map");
}

}  // namespace
}  // namespace strata::testing
