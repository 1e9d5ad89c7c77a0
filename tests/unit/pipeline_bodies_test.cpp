// A scene of several bodies (`bodies:`): each body's pipeline read from its file, placed, given the scene's date
// and sun; the camera tied to one of them; and the refusals, each at its line with a fix.
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <strata/log.hpp>

#include "pipeline/scene_placement.hpp"
#include "pipeline_test_fixtures.hpp"

namespace strata::testing {
namespace {

class BodiesTest : public PipelineTest {
 protected:
  BodiesTest() {
    directory_.write("earth.yaml", "strata: 1\nbody: {name: Earth}\nnodes:\n" + kFrameNodes);
    directory_.write("moon.yaml", "strata: 1\nbody: {name: Moon}\nsun: {lon: 70, lat: 1.5}\nnodes:\n" + kFrameNodes);
  }

  // The scene of the Earth and the Moon; `lines` follow `strata: 1` (line 2 on), `moon` is the Moon's entry.
  static std::string earthAndMoon(const std::string& lines, const std::string& moon = "{pipeline: moon.yaml}") {
    return "strata: 1\n" + lines + "bodies:\n  earth: {pipeline: earth.yaml}\n  moon: " + moon + "\n";
  }
};

TEST_F(BodiesTest, EachBodyIsItsOwnPipelineInTheOrderWritten) {
  const Pipeline scene = parse(earthAndMoon("", "{pipeline: moon.yaml, position: [3.844e8, 0, 0]}"));
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.bodies[0].id, "earth");
  EXPECT_EQ(scene.bodies[1].id, "moon");
  EXPECT_EQ(scene.bodies[1].pipeline.body.name, "Moon");
  EXPECT_EQ(scene.bodies[1].pipeline.nodes.size(), 3u);
  EXPECT_EQ(scene.bodies[1].position, glm::dvec3(3.844e8, 0.0, 0.0));
  EXPECT_TRUE(scene.nodes.empty());
  EXPECT_EQ(scene.camera.body, "earth");  // unset: the first
  EXPECT_EQ(scene.body.name, "Earth");    // the camera's body's
}

TEST_F(BodiesTest, TheCameraMayBeTiedToAnyBody) {
  const Pipeline scene = parse(earthAndMoon("camera: {body: moon, altitude: 1.0e6}\n"));
  EXPECT_EQ(scene.camera.body, "moon");
  EXPECT_DOUBLE_EQ(scene.body.radius, 1737400.0);
}

// The scene's date reaches every body; the Earth's sun from it stands over each body where that body sees it,
// in place of a body's own fixed sun.
TEST_F(BodiesTest, EveryBodyTakesTheScenesDateAndSun) {
  const Pipeline scene = parse(earthAndMoon("date: 2024-03-20T18:00Z\n", "{pipeline: moon.yaml, orbit: moon}"));
  const DayNumber date = *parseIsoDate("2024-03-20T18:00Z");
  for (const SceneBody& body : scene.bodies) EXPECT_EQ(body.pipeline.date, date);
  const SubsolarPoint overEarth = *scene.bodies[0].pipeline.sun;  // turned into the Earth's own axes: the same
  EXPECT_NEAR(overEarth.lon, earthSubsolarPoint(date).lon, 1e-9);
  EXPECT_NEAR(overEarth.lat, earthSubsolarPoint(date).lat, 1e-9);
  const SubsolarPoint overMoon = *scene.bodies[1].pipeline.sun;
  EXPECT_EQ(overMoon, sunOver(earthSubsolarPoint(date), placementOf(scene.bodies[1], date)));
  EXPECT_NE(overMoon, (SubsolarPoint{70.0, 1.5}));
}

// The sun from the Moon is the Earth's direction to it turned into the Moon's axes: at a lunar eclipse (2022
// November 8, 10:59 UT) the Moon stands behind the Earth, and the sun over its near side, longitude 0 (the
// Earth's direction), within the Moon's 0.6 degrees from the shadow's axis (moon_orbit_test.cpp) and 1.5 from
// the libration its axes leave out.
TEST_F(BodiesTest, AtALunarEclipseTheSunStandsOverTheMoonsNearSide) {
  SceneBody moon;
  moon.orbit = BodyOrbit::Moon;
  const DayNumber eclipse = *parseIsoDate("2022-11-08T10:59Z");
  const SubsolarPoint sun = sunOver(earthSubsolarPoint(eclipse), placementOf(moon, eclipse));
  EXPECT_NEAR(std::hypot(sun.lon, sun.lat), 0.0, 0.7);
}

// Bodies whose spheres meet are drawn, with a warning that their order may not hold where both show.
TEST_F(BodiesTest, BodiesThatMeetAreWarnedOf) {
  std::vector<LogMessage> warnings;
  const LogSink previous = setLogSink([&warnings](const LogMessage& message) { warnings.push_back(message); });
  parse(earthAndMoon("", "{pipeline: moon.yaml, position: [7.0e6, 0, 0]}"));
  parse(earthAndMoon("", "{pipeline: moon.yaml, position: [9.0e6, 0, 0]}"));
  setLogSink(previous);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].text.find("the bodies 'earth' and 'moon' meet"), std::string::npos) << warnings[0].text;
  EXPECT_NE(warnings[0].text.find("pipeline.yaml:4"), std::string::npos) << warnings[0].text;
}

TEST_F(BodiesTest, AnOrbitNeedsTheScenesDate) {
  const Error error = parseError(earthAndMoon("", "{pipeline: moon.yaml, orbit: moon}"));
  EXPECT_NE(error.problem().find("orbit: moon"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 4);
  EXPECT_NE(error.fix().find("date"), std::string::npos);
}

TEST_F(BodiesTest, TheMoonsOrbitIsAboutTheEarthListedFirst) {
  const Error error = parseError(
      "strata: 1\ndate: 2024-03-20\nbodies:\n  moon: {pipeline: moon.yaml}\n  other: {pipeline: moon.yaml, orbit: "
      "moon}\n");
  EXPECT_NE(error.problem().find("the first body is 'Moon'"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 5);
}

TEST_F(BodiesTest, TheFirstBodyStandsAtTheOrigin) {
  const Error error = parseError("strata: 1\nbodies:\n  earth: {pipeline: earth.yaml, position: [1, 0, 0]}\n");
  EXPECT_NE(error.problem().find("stands at its origin"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 3);
}

TEST_F(BodiesTest, TheCameraNamesABodyOfTheScene) {
  const Error error = parseError(earthAndMoon("camera: {body: mon}\n"));
  EXPECT_NE(error.problem().find("did you mean 'moon'"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 2);
  EXPECT_NE(error.fix().find("'earth', 'moon'"), std::string::npos) << error.fix();
}

TEST_F(BodiesTest, ACameraBodyWithoutBodiesIsRefused) {
  const Error error = parseError("strata: 1\ncamera: {body: moon}\nnodes:\n" + kFrameNodes);
  EXPECT_NE(error.problem().find("draws one body"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 2);
}

TEST_F(BodiesTest, ASceneOfBodiesHasNoNodesOfItsOwn) {
  const Error error = parseError(earthAndMoon("nodes:\n" + kFrameNodes));
  EXPECT_NE(error.problem().find("its own 'nodes'"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 3);
}

// Each body's air is its own file's: an atmosphere beside `bodies:` would be no body's.
TEST_F(BodiesTest, ASceneOfBodiesHasNoAtmosphereOfItsOwn) {
  const Error error = parseError(earthAndMoon("atmosphere: {}\n"));
  EXPECT_NE(error.problem().find("its own 'atmosphere'"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 2);
}

// A body's own file gives it air, which it keeps in the scene.
TEST_F(BodiesTest, EachBodyKeepsItsOwnAtmosphere) {
  directory_.write("earth.yaml",
                   "strata: 1\nbody: {name: Earth}\natmosphere: {mie_scattering: 2.0e-5, "
                   "mie_extinction: 2.2e-5}\nnodes:\n" +
                       kFrameNodes);
  const Pipeline scene = parse(earthAndMoon(""));
  ASSERT_TRUE(scene.bodies[0].pipeline.atmosphere.has_value());
  EXPECT_DOUBLE_EQ(scene.bodies[0].pipeline.atmosphere->mieScattering, 2.0e-5);
  EXPECT_FALSE(scene.bodies[1].pipeline.atmosphere.has_value());
}

TEST_F(BodiesTest, ABodysPipelineDrawsOneBody) {
  directory_.write("scene.yaml", earthAndMoon(""));
  const Error error =
      parseError("strata: 1\nbodies:\n  earth: {pipeline: earth.yaml}\n  both: {pipeline: scene.yaml}\n");
  EXPECT_NE(error.problem().find("a scene of several bodies itself"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 4);
}

// A scene that names itself as a body is refused, not read without end.
TEST_F(BodiesTest, ASceneThatNamesItselfIsRefused) {
  const Error error = errorFrom([&] {
    loadPipeline(directory_.write("self.yaml",
                                  "strata: 1\nbodies:\n  earth: {pipeline: earth.yaml}\n  again: "
                                  "{pipeline: self.yaml}\n"),
                 {}, registry_);
  });
  EXPECT_NE(error.problem().find("a scene of several bodies itself"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 4);
}

TEST_F(BodiesTest, AnEntryWithoutAPipelineIsRefused) {
  const Error error = parseError("strata: 1\nbodies:\n  earth: {position: [0, 0, 0]}\n");
  EXPECT_NE(error.problem().find("names no pipeline"), std::string::npos) << error.problem();
  EXPECT_EQ(error.where().line, 3);
}

// An error inside a body's file names that file and its line.
TEST_F(BodiesTest, AnErrorInABodysFileNamesThatFile) {
  directory_.write("broken.yaml", "strata: 1\nbody: {name: Moon}\nnodes:\n  frame: {type: output.imag}\n");
  const Error error =
      parseError("strata: 1\nbodies:\n  earth: {pipeline: earth.yaml}\n  moon: {pipeline: broken.yaml}\n");
  EXPECT_NE(error.where().file.find("broken.yaml"), std::string::npos) << error.where().str();
  EXPECT_EQ(error.where().line, 4);
}

// Every file the scene reads, its bodies' included, is kept from outputs (strata/host/output_file.hpp).
TEST_F(BodiesTest, TheBodiesFilesAreTheScenesInputs) {
  const Pipeline scene = parse(earthAndMoon(""));
  const std::vector<std::filesystem::path> files = pipelineInputFiles(scene);
  const auto reads = [&](const std::string& name) {
    return std::any_of(files.begin(), files.end(), [&](const auto& file) { return file.filename() == name; });
  };
  EXPECT_TRUE(reads("earth.yaml"));
  EXPECT_TRUE(reads("moon.yaml"));
  EXPECT_TRUE(reads("earth.jpg"));
}

}  // namespace
}  // namespace strata::testing
