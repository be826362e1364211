// FreeBOT's parameters: config/freebot.yaml through YamlParameterSource equals the code's
// defaults to the bit (so the nodes and sphere_sim behave as before the file existed) and
// Table II; a bad or missing value is named with its key, its value and the file.

#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

#include <urdf_parser/urdf_parser.h>

#include <cmath>

#include "spherical_robots/config/freebot_config.hpp"
#include "spherical_robots/config/freebot_description.hpp"
#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "expect_invalid_argument.hpp"
#include "temp_yaml.hpp"

namespace {

// CMakeLists.txt defines SPHERICAL_ROBOTS_SOURCE_DIR: the shipped file of the source tree.
const std::string kShipped = SPHERICAL_ROBOTS_SOURCE_DIR "/config/freebot.yaml";

using spherical_robots::config::freebotChain;
using spherical_robots::config::freebotRobotDescription;
using spherical_robots::config::sphereRadiusFromUrdf;
using spherical_robots::config::freebotGoalExecutive;
using spherical_robots::config::YamlParameterSource;
using spherical_robots::freebot::FreebotChain;
using spherical_robots::freebot::GoalExecutiveParameters;
using spherical_robots::freebot::TrolleyGeometry;

using spherical_robots::test_support::TempYaml;

/// Every number of the parameters, for comparison as a whole.
auto everyField(const GoalExecutiveParameters& p) {
  return std::make_tuple(
      p.ik.position_tolerance, p.ik.orientation_tolerance, p.ik.restarts, p.ik.max_iterations,
      p.gains.forward, p.gains.steering, p.gains.alignment, p.limits.max_forward_speed,
      p.limits.max_steering_speed, p.limits.max_wheel_speed, p.limits.heading_tolerance,
      p.limits.contact_tolerance, p.limits.steering_distance, p.position_tolerance,
      p.orientation_tolerance, p.max_replans, p.timeout);
}

TEST(FreebotConfig, ShippedFileEqualsTheDefaultsToTheBit) {
  const YamlParameterSource source(kShipped);
  EXPECT_EQ(everyField(freebotGoalExecutive(source)), everyField(GoalExecutiveParameters{}));

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
      {"freebot: {goal: {position_tolerance: -1.0e-4}}",
       {"freebot/goal/position_tolerance", "-0.0001", "> 0"}},
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

// The description is the chain the nodes integrate: one sphere per module of exactly the radii
// they read, in a tree rooted at the base, read back by urdfdom (what rviz's RobotModel uses).
TEST(FreebotDescription, IsTheChainOfTheRadiiTheNodesUse) {
  const std::vector<double> radii = freebotChain(YamlParameterSource(kShipped)).manipulator().radii();
  const std::string xml = freebotRobotDescription(radii);
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(xml);
  ASSERT_TRUE(model) << xml;
  EXPECT_EQ(model->getRoot()->name, "link0");
  std::vector<urdf::LinkSharedPtr> links;
  model->getLinks(links);
  EXPECT_EQ(links.size(), radii.size());
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const std::string link = "link" + std::to_string(i);
    EXPECT_EQ(sphereRadiusFromUrdf(xml, link), radii[i]) << link;  // to the bit: 17 digits
    if (i == 0) continue;
    const urdf::JointConstSharedPtr joint = model->getJoint("joint" + std::to_string(i));
    ASSERT_TRUE(joint) << i;
    EXPECT_EQ(joint->type, urdf::Joint::FLOATING);
    EXPECT_EQ(joint->parent_link_name, "link" + std::to_string(i - 1));
    EXPECT_EQ(joint->child_link_name, link);
  }
  const std::vector<double> odd = {0.04, 1.0 / 3.0, 0.0123456789012345};
  EXPECT_EQ(sphereRadiusFromUrdf(freebotRobotDescription(odd), "link1"), odd[1]);
}

TEST(FreebotDescription, RefusesWhatIsNoChain) {
  EXPECT_INVALID_ARGUMENT(freebotRobotDescription({0.034}), "1 radii");
  EXPECT_INVALID_ARGUMENT(freebotRobotDescription({0.034, 0.0}), "l_1");
  EXPECT_INVALID_ARGUMENT(freebotRobotDescription({std::nan(""), 0.034}), "l_0");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
