// FreeBOT's parameters: config/freebot.yaml through YamlParameterSource equals the code's
// defaults to the bit (so the nodes and sphere_sim behave as before the file existed) and
// Table II; a bad or missing value is named with its key, its value and the file.

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>
#include <unistd.h>

#include "spherical_robots/config/freebot_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "expect_invalid_argument.hpp"

#ifndef SPHERICAL_ROBOTS_SOURCE_DIR
#error "SPHERICAL_ROBOTS_SOURCE_DIR must be defined (CMakeLists.txt)"
#endif

namespace {

using spherical_robots::config::freebotChain;
using spherical_robots::config::freebotGoalExecutive;
using spherical_robots::config::YamlParameterSource;
using spherical_robots::freebot::FreebotChain;
using spherical_robots::freebot::GoalExecutiveParameters;
using spherical_robots::freebot::TrolleyGeometry;

const std::string kShipped = SPHERICAL_ROBOTS_SOURCE_DIR "/config/freebot.yaml";

// A YAML file in the test's temp directory, removed when the test ends.
class TempYaml {
 public:
  explicit TempYaml(const std::string& text) {
    static int counter = 0;
    path_ = ::testing::TempDir() + "freebot_config_" + std::to_string(::getpid()) + "_" +
            std::to_string(counter++) + ".yaml";
    std::ofstream(path_) << text;
  }
  ~TempYaml() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

TEST(FreebotConfig, ShippedFileEqualsTheDefaultsToTheBit) {
  const YamlParameterSource source(kShipped);
  const GoalExecutiveParameters read = freebotGoalExecutive(source);
  const GoalExecutiveParameters defaults;
  EXPECT_EQ(read.ik.position_tolerance, defaults.ik.position_tolerance);
  EXPECT_EQ(read.ik.orientation_tolerance, defaults.ik.orientation_tolerance);
  EXPECT_EQ(read.ik.restarts, defaults.ik.restarts);
  EXPECT_EQ(read.ik.max_iterations, defaults.ik.max_iterations);
  EXPECT_EQ(read.gains.forward, defaults.gains.forward);
  EXPECT_EQ(read.gains.steering, defaults.gains.steering);
  EXPECT_EQ(read.gains.alignment, defaults.gains.alignment);
  EXPECT_EQ(read.limits.max_forward_speed, defaults.limits.max_forward_speed);
  EXPECT_EQ(read.limits.max_steering_speed, defaults.limits.max_steering_speed);
  EXPECT_EQ(read.limits.max_wheel_speed, defaults.limits.max_wheel_speed);
  EXPECT_EQ(read.limits.heading_tolerance, defaults.limits.heading_tolerance);
  EXPECT_EQ(read.limits.contact_tolerance, defaults.limits.contact_tolerance);
  EXPECT_EQ(read.limits.steering_distance, defaults.limits.steering_distance);
  EXPECT_EQ(read.position_tolerance, defaults.position_tolerance);
  EXPECT_EQ(read.orientation_tolerance, defaults.orientation_tolerance);
  EXPECT_EQ(read.max_replans, defaults.max_replans);
  EXPECT_EQ(read.timeout, defaults.timeout);

  const FreebotChain chain = freebotChain(source);
  const TrolleyGeometry geometry;
  // Four modules of Table II's 0.034 m on a 0.034 m base, as launch/freebot_stack.launch's
  // default modules:=4 radius:=0.034.
  EXPECT_EQ(chain.manipulator().radii(), std::vector<double>(5, 0.034));
  for (std::size_t i = 0; i < chain.moduleCount(); ++i) {
    EXPECT_EQ(chain.trolley(i).wheelRadius(), geometry.wheel_radius);
    EXPECT_EQ(chain.trolley(i).wheelInterval(), geometry.wheel_interval);
    EXPECT_EQ(chain.trolley(i).innerRadius(), 0.034 - geometry.shell_thickness);
  }
}

TEST(FreebotConfig, DefaultsAreTableII) {
  // Table II: k_s = 3, k_φ1 = 6, k_φ2 = 1; r_w = 0.005 m, l_w = 0.046 m, r_out − r_in = 0.002 m.
  const GoalExecutiveParameters defaults;
  EXPECT_EQ(defaults.gains.forward, 3.0);
  EXPECT_EQ(defaults.gains.steering, 6.0);
  EXPECT_EQ(defaults.gains.alignment, 1.0);
  const TrolleyGeometry geometry;
  EXPECT_EQ(geometry.wheel_radius, 0.005);
  EXPECT_EQ(geometry.wheel_interval, 0.046);
  EXPECT_EQ(geometry.shell_thickness, 0.002);
}

TEST(FreebotConfig, AbsentKeysKeepTheDefaultsButTheRadiiAreRequired) {
  const TempYaml radii_only("freebot: {radii: [0.04, 0.03]}\n");
  const YamlParameterSource source(radii_only.path());
  EXPECT_EQ(freebotChain(source).manipulator().radii(), (std::vector<double>{0.04, 0.03}));
  EXPECT_EQ(freebotGoalExecutive(source).timeout, GoalExecutiveParameters().timeout);
  const TempYaml empty("freebot: {trolley: {wheel_radius: 0.004}}\n");
  EXPECT_INVALID_ARGUMENT(freebotChain(YamlParameterSource(empty.path())), "freebot/radii",
                          "required", empty.path());
}

TEST(FreebotConfig, BadValuesNameTheKeyTheValueAndTheFile) {
  const struct {
    std::string yaml;
    std::vector<std::string> needles;
  } cases[] = {
      {"freebot: {goal: {position_tolerance: -1.0e-4}}", {"freebot/goal/position_tolerance", "-0.0001", "> 0"}},
      {"freebot: {goal: {max_replans: 1.5}}", {"freebot/goal/max_replans", "1.5", "integer >= 0"}},
      {"freebot: {ik: {max_iterations: 0}}", {"freebot/ik/max_iterations", "integer >= 1"}},
      {"freebot: {drive: {max_wheel_speed: .nan}}", {"freebot/drive/max_wheel_speed", "finite"}},
      {"freebot: {gains: {steering: fast}}", {"freebot/gains/steering", "number", "fast"}},
  };
  for (const auto& c : cases) {
    const TempYaml file(c.yaml);
    const YamlParameterSource source(file.path());
    for (const std::string& needle : c.needles)
      EXPECT_INVALID_ARGUMENT(freebotGoalExecutive(source), needle, file.path());
  }
}

TEST(FreebotConfig, ABadChainNamesItsKeys) {
  const TempYaml zero("freebot: {radii: [0.034, 0.0, 0.034]}\n");
  EXPECT_INVALID_ARGUMENT(freebotChain(YamlParameterSource(zero.path())), "freebot/radii",
                          "freebot/trolley", zero.path());
  const TempYaml text("freebot: {radii: [0.034, big]}\n");
  EXPECT_INVALID_ARGUMENT(freebotChain(YamlParameterSource(text.path())), "freebot/radii",
                          "list of numbers", text.path());
  const TempYaml scalar("freebot: {radii: 0.034}\n");
  EXPECT_INVALID_ARGUMENT(freebotChain(YamlParameterSource(scalar.path())), "freebot/radii",
                          "list of numbers");
  const TempYaml thick("freebot: {radii: [0.034, 0.034], trolley: {shell_thickness: 0.05}}\n");
  EXPECT_INVALID_ARGUMENT(freebotChain(YamlParameterSource(thick.path())), "shell thickness",
                          "0.05");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
