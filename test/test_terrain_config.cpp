// The terrain scenario's parameters: config/terrain.yaml through YamlParameterSource and
// loadTerrainConfig, the factories for surfaces and paths, and the sphere radius read from a URDF.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>
#include <unistd.h>

#include "spherical_robots/config/actuator_models.hpp"
#include "spherical_robots/config/layered_parameter_source.hpp"
#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "expect_invalid_argument.hpp"
#include "shipped_config.hpp"
#include "temp_yaml.hpp"

namespace {

using spherical_robots::config::loadTerrainConfig;
using spherical_robots::config::makePath;
using spherical_robots::config::makePursuitController;
using spherical_robots::config::makeSurface;
using spherical_robots::config::SurfaceSpec;
using spherical_robots::config::sphereRadiusFromUrdf;
using spherical_robots::config::TerrainConfig;
using spherical_robots::config::YamlParameterSource;
using spherical_robots::terrain::PursuitGains;
using spherical_robots::terrain::PursuitLaw;
using spherical_robots::terrain::RobotType;

constexpr double kPi = 3.14159265358979323846;
const std::string& kShipped = spherical_robots::test_support::kShippedTerrainYaml;

using spherical_robots::test_support::TempYaml;

TerrainConfig loadText(const std::string& text) {
  const TempYaml file(text);
  return loadTerrainConfig(YamlParameterSource(file.path()));
}

// The documented defaults: config/terrain.yaml ("the defaults"), k_e = 0.5 m for all.
void expectDocumentedGains(const TerrainConfig& c) {
  const PursuitGains& g3r = c.gains.at(RobotType::ThreeAxisRolling);
  EXPECT_EQ(g3r.k_theta, 2.0);
  EXPECT_EQ(g3r.k_phi1, 2.0);
  EXPECT_EQ(g3r.k_phi2, 0.3);
  EXPECT_EQ(g3r.k_psi, 1.0);
  const PursuitGains& g2r = c.gains.at(RobotType::TwoAxisRolling);
  EXPECT_EQ(g2r.k_theta1, 3.0);
  EXPECT_EQ(g2r.k_theta2, 0.3);
  EXPECT_EQ(g2r.k_phi1, 3.0);
  EXPECT_EQ(g2r.k_phi2, 0.3);
  const PursuitGains& grt = c.gains.at(RobotType::RollingAndTurning);
  EXPECT_EQ(grt.k_theta, 2.0);
  EXPECT_EQ(grt.k_psi, 1.0);
  const PursuitGains& grs = c.gains.at(RobotType::RollingAndSteering);
  EXPECT_EQ(grs.k_alpha, 0.5);
  EXPECT_EQ(grs.k_phi, 2.0);
  for (const auto& [type, g] : c.gains) EXPECT_EQ(g.k_e, 0.5);
}

void expectDocumentedScenario(const TerrainConfig& c) {
  EXPECT_EQ(c.surface.type, "cosine");  // eq 59, a = 0.2 m, w = 2
  EXPECT_EQ(c.surface.amplitude, 0.2);
  EXPECT_EQ(c.surface.frequency, 2.0);
  EXPECT_EQ(c.circle_radius, 2.0);  // eq 60: 2 cos(5t/100)
  EXPECT_EQ(c.circle_angular_rate, 0.05);
  EXPECT_EQ(c.diamond_half_diagonal, 2.0);  // diagonals of 4 m, the circle's diameter
  EXPECT_EQ(c.diamond_speed, 0.1);          // the circle's speed, 2 m x 0.05 rad/s
  EXPECT_NEAR(c.tilt_limit, kPi / 3, 1e-15);  // section 6: "a limitation of pi/3"
}

// ------------------------------------------------------------------------------------------

TEST(TerrainConfig, ShippedFileGivesThePapersScenarioAndTheDocumentedGains) {
  const TerrainConfig c = loadTerrainConfig(YamlParameterSource(kShipped));
  expectDocumentedScenario(c);
  EXPECT_EQ(c.surface.height_map, "maps/hills.yaml");  // the example map, for type height_map
  EXPECT_EQ(c.gains.size(), 4u);
  expectDocumentedGains(c);
}

TEST(TerrainConfig, MissingKeysKeepTheDocumentedDefaults) {
  // Every gain key is missing here; each type must still get its documented default (2R's k_phi1
  // is 3.0 in config/terrain.yaml, not the 3R value 2.0 that PursuitGains{} carries).
  for (const char* text : {"{}\n", "terrain:\n  surface:\n    amplitude: 0.3\n"}) {
    SCOPED_TRACE(text);
    TerrainConfig c = loadText(text);
    EXPECT_EQ(c.surface.amplitude, text[0] == '{' ? 0.2 : 0.3);
    c.surface.amplitude = 0.2;
    expectDocumentedScenario(c);
    EXPECT_EQ(c.gains.size(), 4u);
    expectDocumentedGains(c);
  }
}

// The smooth law's gains as docs/conventions.md ("The smooth law") documents them.
void expectDocumentedSmoothGains(const TerrainConfig& c) {
  ASSERT_EQ(c.smooth_gains.size(), 4u);
  for (const auto& [type, g] : c.smooth_gains) {
    SCOPED_TRACE(toString(type));
    const bool steers = type == RobotType::RollingAndTurning || type == RobotType::RollingAndSteering;
    const bool rs = type == RobotType::RollingAndSteering;
    EXPECT_EQ(g.window, steers ? 1.0 : 0.5);
    EXPECT_EQ(g.lead, type == RobotType::RollingAndTurning ? 0.25 : rs ? 0.5 : 0.0);
    EXPECT_EQ(g.approach_speed, rs ? 0.2 : 0.5);
    EXPECT_EQ(g.along_gain, 4.0);
    EXPECT_EQ(g.cross_gain, rs ? 1.5 : 3.0);
    EXPECT_EQ(g.heading_gain, type == RobotType::RollingAndTurning ? 4.0 : 2.0);
    EXPECT_EQ(g.tilt_gain, 3.0);
    EXPECT_EQ(g.max_tilt, 0.8);
    EXPECT_EQ(g.max_tilt_rate, 1.0);
    EXPECT_EQ(g.min_speed, rs ? 0.05 : 0.01);
  }
}

TEST(TerrainConfig, ShippedAndMissingSmoothGainsAreTheDocumentedOnes) {
  expectDocumentedSmoothGains(loadTerrainConfig(YamlParameterSource(kShipped)));
  expectDocumentedSmoothGains(loadText("{}\n"));
  const TerrainConfig c = loadText("terrain:\n  smooth_gains:\n    RS: {heading_gain: 2.5}\n");
  EXPECT_EQ(c.smooth_gains.at(RobotType::RollingAndSteering).heading_gain, 2.5);
  EXPECT_EQ(c.smooth_gains.at(RobotType::RollingAndSteering).cross_gain, 1.5);  // RS's own
  EXPECT_EQ(c.smooth_gains.at(RobotType::RollingAndTurning).heading_gain, 4.0);
}

TEST(TerrainConfig, BadSmoothGainsAreRejectedNamingTheKeyTheGainAndTheFile) {
  const TempYaml file("terrain:\n  smooth_gains:\n    RT: {heading_gain: -4}\n");
  EXPECT_INVALID_ARGUMENT(loadTerrainConfig(YamlParameterSource(file.path())),
                          "terrain/smooth_gains/RT", "heading_gain", "got -4", file.path());
  // An RS tilt set-point bound at or past the tilt limit is caught where both are known.
  const TerrainConfig c = loadText("terrain:\n  smooth_gains:\n    RS: {max_tilt: 1.2}\n");
  EXPECT_INVALID_ARGUMENT(
      makePursuitController(PursuitLaw::Smooth, RobotType::RollingAndSteering, c, 0.2),
      "max_tilt", "1.2", "limit");
  EXPECT_NO_THROW(makePursuitController(PursuitLaw::Paper, RobotType::RollingAndSteering, c, 0.2));
}

TEST(MakePursuitController, BuildsTheNamedLawWithTheScenariosGains) {
  const TerrainConfig c = loadTerrainConfig(YamlParameterSource(kShipped));
  for (RobotType type : {RobotType::ThreeAxisRolling, RobotType::RollingAndSteering}) {
    const auto paper = makePursuitController(PursuitLaw::Paper, type, c, 0.2);
    const auto smooth = makePursuitController(PursuitLaw::Smooth, type, c, 0.2);
    EXPECT_EQ(paper->type(), type);
    EXPECT_EQ(smooth->type(), type);
    EXPECT_EQ(paper->velocityWindow().length, 0.0);  // eqs 55-58 take p_d'(t)
    EXPECT_EQ(smooth->velocityWindow().length, c.smooth_gains.at(type).window);
    EXPECT_EQ(smooth->velocityWindow().lead, c.smooth_gains.at(type).lead);
  }
}

TEST(TerrainConfig, OneOverriddenGainLeavesTheOthersAndSharedKeAppliesToAllTypes) {
  const TerrainConfig c = loadText("terrain:\n  gains:\n    k_e: 0.7\n    3R: {k_psi: 1.5}\n");
  EXPECT_EQ(c.gains.at(RobotType::ThreeAxisRolling).k_psi, 1.5);
  EXPECT_EQ(c.gains.at(RobotType::ThreeAxisRolling).k_theta, 2.0);
  EXPECT_EQ(c.gains.at(RobotType::RollingAndTurning).k_psi, 1.0);  // RT's own k_psi untouched
  for (const auto& [type, g] : c.gains) EXPECT_EQ(g.k_e, 0.7);
}

struct BadValue {
  const char* label;
  const char* yaml;
  const char* key;  // what the message must name
};

class TerrainConfigBadValue : public ::testing::TestWithParam<BadValue> {};

TEST_P(TerrainConfigBadValue, ThrowsNamingTheKeyAndTheFile) {
  const auto c = GetParam();
  const TempYaml file(c.yaml);
  EXPECT_INVALID_ARGUMENT(loadTerrainConfig(YamlParameterSource(file.path())), c.key, file.path());
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, TerrainConfigBadValue,
    ::testing::Values(
        BadValue{"StringGain", "terrain:\n  gains:\n    3R: {k_theta: fast}\n", "k_theta"},
        BadValue{"NanGain", "terrain:\n  gains:\n    RT: {k_psi: .nan}\n", "k_psi"},
        BadValue{"InfGain", "terrain:\n  gains:\n    RS: {k_alpha: .inf}\n", "k_alpha"},
        BadValue{"NegativeGain", "terrain:\n  gains:\n    2R: {k_phi2: -0.3}\n", "k_phi2"},
        BadValue{"NegativeRsTiltGain", "terrain:\n  gains:\n    RS: {k_phi: -2}\n", "k_phi"},
        BadValue{"ZeroKe", "terrain:\n  gains:\n    k_e: 0\n", "k_e"},
        BadValue{"StringAmplitude", "terrain:\n  surface:\n    amplitude: high\n", "amplitude"},
        BadValue{"NanFrequency", "terrain:\n  surface:\n    frequency: .nan\n", "frequency"},
        BadValue{"StringCircleRadius", "terrain:\n  paths:\n    circle: {radius: big}\n", "radius"},
        BadValue{"NanTiltLimit", "terrain:\n  rs_tilt_limit: .nan\n", "rs_tilt_limit"},
        BadValue{"ListWhereNumber", "terrain:\n  paths:\n    diamond: {speed: [1, 2]}\n", "speed"}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(YamlParameterSource, RejectsAMissingOrUnparsableFileNamingIt) {
  const std::string missing = ::testing::TempDir() + "no_such_terrain_config.yaml";
  EXPECT_INVALID_ARGUMENT(YamlParameterSource{missing}, missing);
  const TempYaml broken("terrain: [unclosed\n  surface: {\n");
  EXPECT_INVALID_ARGUMENT(YamlParameterSource{broken.path()}, broken.path());
}

TEST(YamlParameterSource, ReadsNestedKeysAndReportsAbsentOnes) {
  const TempYaml file("a:\n  b:\n    c: 1.5\n    s: hello\n");
  const YamlParameterSource src(file.path());
  EXPECT_EQ(src.number("a/b/c").value(), 1.5);
  EXPECT_EQ(src.text("a/b/s").value(), "hello");
  EXPECT_FALSE(src.number("a/b/missing").has_value());
  EXPECT_FALSE(src.number("x/y").has_value());
  EXPECT_THROW(src.number("a/b/s"), std::invalid_argument);
  EXPECT_EQ(src.origin(), file.path());
}

TEST(YamlParameterSource, NamesTheLineOfABadValue) {
  const TempYaml file("a:\n  b: 1\n  c: twelve\n");
  EXPECT_INVALID_ARGUMENT(YamlParameterSource(file.path()).number("a/c"), file.path() + " line 3",
                          "'a/c'", "twelve");
}

TEST(YamlParameterSource, RefusesAKeyGivenTwiceWhoseLaterValueWouldBeIgnored) {
  // yaml-cpp keeps both and reads the first; the author of the second meant it.
  const TempYaml top("a: 1\nb: 2\na: 3\n");
  EXPECT_INVALID_ARGUMENT(YamlParameterSource{top.path()}, top.path() + " line 3", "'a'", "twice");
  const TempYaml nested("a:\n  list:\n    - {x: 1, x: 2}\n");
  EXPECT_INVALID_ARGUMENT(YamlParameterSource{nested.path()}, "line 3", "'a/list/x'", "twice");
}

TEST(YamlParameterSource, RefusesATopLevelThatIsNoDictionary) {
  const TempYaml list("- 1\n- 2\n");
  EXPECT_INVALID_ARGUMENT(YamlParameterSource{list.path()}, list.path(), "top level", "dictionary");
}

TEST(YamlParameterSource, WarnsOfAnEmptyFile) {
  const TempYaml empty("# only a comment\n");
  std::string warning;
  const YamlParameterSource src(empty.path(), [&](const std::string& w) { warning = w; });
  EXPECT_NE(warning.find(empty.path()), std::string::npos) << warning;
  EXPECT_NE(warning.find("no parameters"), std::string::npos) << warning;
  EXPECT_FALSE(src.number("a").has_value());
}

TEST(YamlParameterSource, RefusesAValueWhereAKeyNeedsADictionary) {
  // terrain/surface: 3 would otherwise leave every surface parameter at its default.
  const TempYaml file("terrain:\n  surface: 3\n");
  EXPECT_INVALID_ARGUMENT(YamlParameterSource(file.path()).number("terrain/surface/amplitude"),
                          file.path() + " line 2", "'terrain/surface'", "dictionary");
  EXPECT_INVALID_ARGUMENT(loadTerrainConfig(YamlParameterSource(file.path())), "terrain/surface");
}

TEST(YamlParameterSource, ListsTheKeysNothingReadWithTheirLines) {
  const TempYaml file("a:\n  b: 1\n  typo: 2\n  list: [1, 2]\n  nested:\n    c: x\nd: 4\n");
  const YamlParameterSource src(file.path());
  src.number("a/b");
  src.numbers("a/list");
  src.number("a/absent");
  auto keys = [](const std::vector<YamlParameterSource::Key>& unread) {
    std::vector<std::string> text;
    for (const auto& k : unread) text.push_back(k.key + ":" + std::to_string(k.line));
    return text;
  };
  EXPECT_EQ(keys(src.unreadKeys("")), (std::vector<std::string>{"a/typo:3", "a/nested/c:6", "d:7"}));
  EXPECT_EQ(keys(src.unreadKeys("a/nested")), (std::vector<std::string>{"a/nested/c:6"}));
  src.text("a/nested/c");
  EXPECT_TRUE(src.gives("d"));
  EXPECT_EQ(keys(src.unreadKeys("")), (std::vector<std::string>{"a/typo:3", "d:7"}));
}

TEST(YamlParameterSource, TheLoadersReadEveryKeyOfTheShippedTerrainFileButTheStacksOwn) {
  // What sphere_sim terrain's warning of unused parameters relies on: nothing else is left.
  const YamlParameterSource src(SPHERICAL_ROBOTS_SOURCE_DIR "/config/terrain.yaml");
  loadTerrainConfig(src);
  std::vector<std::string> unread;
  for (const auto& k : src.unreadKeys("")) unread.push_back(k.key);
  EXPECT_EQ(unread, (std::vector<std::string>{"pure_pursuit_controller/untimed_speed"}));
}

// fuzz_load_height_map's finding (test/fuzz/corpus/fuzz_load_height_map/list_as_key.yaml): a key
// that is a YAML list, as a line "[-8.05, -4.05, 0.0]: x" makes one, escaped the readers as
// yaml-cpp's conversion error (a height map's YAML ended the process); the file is now refused.
TEST(YamlParameterSource, RejectsAKeyThatIsNotANameNamingTheFileAndLine) {
  const TempYaml top("image: grid.pgm\n[-8.05, -4.05, 0.0]: corner\n");
  EXPECT_INVALID_ARGUMENT(YamlParameterSource{top.path()}, top.path() + " line 2", "-8.05",
                          "expected a name");
  const TempYaml nested("image: grid.pgm\nterrain:\n  {a: 1}: 2\n");
  EXPECT_INVALID_ARGUMENT(YamlParameterSource{nested.path()}, nested.path() + " line 3",
                          "a key of 'terrain'", "expected a name");
}

// ------------------------------------------------------------------------------------------
// Factories.

TEST(LayeredParameterSource, RollerYamlOverTerrainYamlIsWhatTheRollerStacksNodesRead) {
  // launch/roller_stack.launch loads config/terrain.yaml, then config/roller.yaml: a later file
  // overrides key by key and leaves the rest.
  std::vector<std::unique_ptr<spherical_robots::config::ParameterSource>> layers;
  layers.push_back(std::make_unique<YamlParameterSource>(kShipped));
  layers.push_back(std::make_unique<YamlParameterSource>(SPHERICAL_ROBOTS_SOURCE_DIR
                                                         "/config/roller.yaml"));
  const spherical_robots::config::LayeredParameterSource both(std::move(layers));
  const TerrainConfig c = loadTerrainConfig(both);
  EXPECT_EQ(c.surface.type, "plane");            // roller.yaml's
  EXPECT_EQ(c.surface.amplitude, 0.2);           // terrain.yaml's, not overridden
  EXPECT_EQ(c.smooth_gains.at(RobotType::TwoAxisRolling).approach_speed, 0.2);  // roller.yaml's
  EXPECT_EQ(c.smooth_gains.at(RobotType::TwoAxisRolling).along_gain, 4.0);      // terrain.yaml's
  EXPECT_EQ(c.circle_radius, 2.0);
  EXPECT_EQ(both.text("terrain/surface/type"), std::optional<std::string>("plane"));
  EXPECT_EQ(both.number("absent/key"), std::nullopt);
  const auto keys = both.keys("terrain/surface");
  ASSERT_TRUE(keys.has_value());
  for (const char* key : {"type", "amplitude", "frequency", "offset"})
    EXPECT_NE(std::find(keys->begin(), keys->end(), key), keys->end()) << key;
  EXPECT_NE(both.origin().find("roller.yaml"), std::string::npos);
  EXPECT_THROW(spherical_robots::config::LayeredParameterSource({}), std::invalid_argument);
}

TEST(ActuatorModels, ShippedRealisticFileAndEveryRuleOfTheReader) {
  using spherical_robots::config::loadActuatorModels;
  const auto shipped = loadActuatorModels(
      YamlParameterSource(SPHERICAL_ROBOTS_SOURCE_DIR "/config/actuators_realistic.yaml"),
      {"theta", "phi"});
  ASSERT_EQ(shipped.models.size(), 2u);
  for (const auto& model : shipped.models) {  // the file's comment: 50 ms lag, 10 ms, 4096 counts
    EXPECT_EQ(model.time_constant, 0.05);
    EXPECT_EQ(model.dead_time, 0.01);
    EXPECT_EQ(model.position_resolution, 2 * kPi / 4096);
    EXPECT_EQ(model.velocity_noise, 0.02);
  }
  EXPECT_EQ(shipped.noise_seed, 42u);
  // models/<name> overrides default_model field by field; absent fields are 0 (off).
  const TempYaml overridden("default_model: {time_constant: 0.1}\nmodels: {phi: {dead_time: 0.02}}\n");
  const auto models = loadActuatorModels(YamlParameterSource(overridden.path()), {"theta", "phi"});
  EXPECT_EQ(models.models[0].time_constant, 0.1);
  EXPECT_EQ(models.models[0].dead_time, 0.0);
  EXPECT_EQ(models.models[1].time_constant, 0.1);
  EXPECT_EQ(models.models[1].dead_time, 0.02);
  EXPECT_EQ(models.noise_seed, 0u);
  const std::pair<const char*, const char*> bad[] = {
      {"default_model: {lag: 0.1}\n", "default_model/lag"},
      {"models: {psi: {dead_time: 0.1}}\n", "models/psi"},
      {"default_model: {dead_time: -0.1}\n", "default_model/dead_time"},
      {"noise_seed: 1.5\n", "noise_seed"},
      {"noise_seed: -1\n", "noise_seed"},
      {"models: [1, 2]\n", "models"}};
  for (const auto& [text, key] : bad) {
    const TempYaml file(text);
    try {
      loadActuatorModels(YamlParameterSource(file.path()), {"theta", "phi"});
      ADD_FAILURE() << "accepted: " << text;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(file.path()), std::string::npos) << e.what();
    }
  }
}

TEST(TerrainConfig, HeightMapTypeReadsTheMapsFile) {
  const TerrainConfig c =
      loadText("terrain:\n  surface:\n    type: height_map\n    height_map: /maps/site.yaml\n");
  EXPECT_EQ(c.surface.type, "height_map");
  EXPECT_EQ(c.surface.height_map, "/maps/site.yaml");
}

TEST(MakeSurface, BuildsTheNamedSurfaceAndRejectsUnknownNames) {
  SurfaceSpec spec;  // cosine, a = 0.2, w = 2
  const auto cosine = makeSurface(spec);
  EXPECT_NEAR(cosine->height(0.3, -1.1), 0.2 * (std::cos(0.6) + std::cos(-2.2) - 2.0), 1e-15);

  spec.type = "tilted_plane";
  spec.slope_x = 0.1;
  spec.slope_y = -0.2;
  spec.offset = 0.5;
  const auto tilted = makeSurface(spec);
  EXPECT_NEAR(tilted->height(2.0, 3.0), 0.5 + 0.2 - 0.6, 1e-15);

  spec.type = "plane";
  spec.slope_x = spec.slope_y = 0.0;
  EXPECT_NEAR(makeSurface(spec)->height(7.0, -3.0), 0.5, 1e-15);

  for (const char* bad : {"bumpy", "Cosine"}) {
    spec.type = bad;
    EXPECT_INVALID_ARGUMENT(makeSurface(spec), bad, "height_map");
  }
  spec.type = "";
  EXPECT_THROW(makeSurface(spec), std::invalid_argument);
  SurfaceSpec zero_frequency;
  zero_frequency.frequency = 0.0;
  EXPECT_THROW(makeSurface(zero_frequency), std::invalid_argument);
}

TEST(MakePath, BuildsTheNamedPathFromTheConfigAndRejectsUnknownNames) {
  TerrainConfig c;
  c.circle_radius = 1.5;
  c.circle_angular_rate = 0.1;
  c.diamond_half_diagonal = 3.0;
  c.diamond_speed = 0.2;
  const auto circle = makePath("circle", c);
  EXPECT_LE((circle->position(5.0) - 1.5 * Eigen::Vector2d(std::cos(0.5), std::sin(0.5))).norm(), 1e-15);
  const auto diamond = makePath("diamond", c);
  EXPECT_LE((diamond->position(0.0) - Eigen::Vector2d(3.0, 0.0)).norm(), 1e-15);
  EXPECT_NEAR(diamond->velocity(1.0).norm(), 0.2, 1e-15);
  for (const char* bad : {"square", "Circle", ""}) {
    EXPECT_THROW(makePath(bad, c), std::invalid_argument) << bad;
  }
  c.circle_radius = -1.0;
  EXPECT_THROW(makePath("circle", c), std::invalid_argument);
}

// ------------------------------------------------------------------------------------------
// sphereRadiusFromUrdf.

std::string urdfWith(const std::string& link_body, const std::string& link = "shell") {
  return "<?xml version=\"1.0\"?>\n<robot name=\"r\">\n  <link name=\"" + link + "\">\n" + link_body +
         "  </link>\n</robot>\n";
}

std::string geometry(const std::string& element, const std::string& shape) {
  return "    <" + element + "><geometry>" + shape + "</geometry></" + element + ">\n";
}

TEST(SphereRadiusFromUrdf, ReadsTheCollisionSphere) {
  EXPECT_EQ(sphereRadiusFromUrdf(urdfWith(geometry("collision", "<sphere radius=\"0.2\"/>")), "shell"), 0.2);
  EXPECT_EQ(sphereRadiusFromUrdf(urdfWith(geometry("collision", "<sphere radius=\"0.35\"/>"), "shell"),
                                 "shell"),
            0.35);
}

TEST(SphereRadiusFromUrdf, PrefersCollisionOverVisualAndFallsBackToVisual) {
  const std::string both = geometry("visual", "<sphere radius=\"0.25\"/>") +
                           geometry("collision", "<sphere radius=\"0.2\"/>");
  EXPECT_EQ(sphereRadiusFromUrdf(urdfWith(both), "shell"), 0.2);
  EXPECT_EQ(sphereRadiusFromUrdf(urdfWith(geometry("visual", "<sphere radius=\"0.25\"/>")), "shell"), 0.25);
}

TEST(SphereRadiusFromUrdf, RejectsWhatIsNotAPositiveSphere) {
  const std::string sphere = geometry("collision", "<sphere radius=\"0.2\"/>");
  EXPECT_THROW(sphereRadiusFromUrdf(urdfWith(geometry("collision", "<box size=\"0.2 0.2 0.2\"/>")), "shell"),
               std::invalid_argument);
  EXPECT_THROW(sphereRadiusFromUrdf(urdfWith(sphere), "missing_link"), std::invalid_argument);
  EXPECT_THROW(sphereRadiusFromUrdf(urdfWith(geometry("collision", "<sphere radius=\"-0.2\"/>")), "shell"),
               std::invalid_argument);
  EXPECT_THROW(sphereRadiusFromUrdf(urdfWith(geometry("collision", "<sphere radius=\"0\"/>")), "shell"),
               std::invalid_argument);
  EXPECT_THROW(sphereRadiusFromUrdf(urdfWith(""), "shell"), std::invalid_argument);  // no geometry at all
  EXPECT_THROW(sphereRadiusFromUrdf("<robot name=\"r\"><link name=\"shell\">", "shell"), std::invalid_argument);
  EXPECT_THROW(sphereRadiusFromUrdf("not xml at all", "shell"), std::invalid_argument);
  EXPECT_THROW(sphereRadiusFromUrdf("", "shell"), std::invalid_argument);
}

TEST(SphereRadiusFromUrdf, GivesUrdfdomsReasonForWhatItRejects) {
  // urdfdom drops a geometry it cannot read and still returns the model: its reason is the error.
  EXPECT_INVALID_ARGUMENT(
      sphereRadiusFromUrdf(urdfWith(geometry("collision", "<sphere radius=\"nan\"/>")), "shell"),
      "not a valid URDF", "radius [nan] is not a valid float");
  EXPECT_INVALID_ARGUMENT(sphereRadiusFromUrdf("<robot name=\"r\"></robot>", "shell"),
                          "not a valid URDF", "No link elements");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
