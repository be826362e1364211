// hardware_interface_sim's parameters (config/hardware_interface_config.hpp) read from YAML, as
// the node reads them from the parameter server: the defaults of docs/hardware_interface.md, the
// effort actuators, and a clear error naming the key for each malformed parameter.
#include <gtest/gtest.h>

#include <string>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/config/hardware_interface_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "temp_yaml.hpp"

namespace config = spherical_robots::config;
namespace hardware = spherical_robots::hardware;
using spherical_robots::test_support::TempYaml;

namespace {

config::HardwareInterfaceSimParameters load(const std::string& yaml) {
  const TempYaml file(yaml);
  return config::loadHardwareInterfaceSimParameters(config::YamlParameterSource(file.path()));
}

}  // namespace

TEST(HardwareInterfaceConfig, DefaultsAreTheDocumentedOnes) {
  const auto p = load("actuator_names: [theta, phi, psi]\n");
  EXPECT_EQ(p.actuator_names, (std::vector<std::string>{"theta", "phi", "psi"}));
  ASSERT_EQ(p.limits.size(), 3u);
  for (const auto& limits : p.limits) {
    EXPECT_EQ(limits.kind, hardware::ActuatorKind::Velocity);
    EXPECT_EQ(limits.max_velocity, 20.0);
    EXPECT_EQ(limits.max_acceleration, 50.0);
  }
  EXPECT_EQ(p.command_timeout, 0.5);
  EXPECT_EQ(p.rate, 100.0);
  EXPECT_EQ(p.max_clock_step, 5.0);
  EXPECT_EQ(p.max_stamp_skew, 1.0);
  EXPECT_EQ(p.models.models.size(), 3u);
  const hardware::SimulatedActuators actuators = config::makeSimulatedActuators(p);
  EXPECT_EQ(actuators.names(), p.actuator_names);
  EXPECT_EQ(actuators.commandTimeout(), 0.5);
}

TEST(HardwareInterfaceConfig, EffortLimitsMakeEffortActuators) {
  const auto p = load(
      "actuator_names: [pendulum_motor, slider_motor]\n"
      "effort_limits: {slider_motor: 200, pendulum_motor: 20.5}\n"
      "max_velocity: 7\ncommand_timeout: 0.1\n");
  EXPECT_EQ(p.limits[0].kind, hardware::ActuatorKind::Effort);
  EXPECT_EQ(p.limits[0].max_effort, 20.5);
  EXPECT_EQ(p.limits[1].kind, hardware::ActuatorKind::Effort);
  EXPECT_EQ(p.limits[1].max_effort, 200.0);
  EXPECT_EQ(p.command_timeout, 0.1);
}

TEST(HardwareInterfaceConfig, MalformedParametersAreNamed) {
  const std::string names = "actuator_names: [theta, phi]\n";
  EXPECT_INVALID_ARGUMENT(load("max_velocity: 5\n"), "actuator_names", "required");
  EXPECT_INVALID_ARGUMENT(load("actuator_names: theta\n"), "actuator_names", "list of strings");
  EXPECT_INVALID_ARGUMENT(load("actuator_names: [theta, [phi]]\n"), "actuator_names");
  EXPECT_INVALID_ARGUMENT(load("actuator_names: []\n"), "actuator_names", "empty");
  EXPECT_INVALID_ARGUMENT(load("actuator_names: [theta, theta]\n"), "actuator_names", "twice");
  EXPECT_INVALID_ARGUMENT(load(names + "max_velocity: -1\n"), "max_velocity", "> 0");
  EXPECT_INVALID_ARGUMENT(load(names + "max_acceleration: 0\n"), "max_acceleration");
  EXPECT_INVALID_ARGUMENT(load(names + "command_timeout: .nan\n"), "command_timeout");
  EXPECT_INVALID_ARGUMENT(load(names + "rate: fast\n"), "rate");
  EXPECT_INVALID_ARGUMENT(load(names + "effort_limits: {slider: 5}\n"), "effort_limits/slider",
                          "names no actuator");
  EXPECT_INVALID_ARGUMENT(load(names + "effort_limits: {phi: -1}\n"), "effort_limits/phi");
  EXPECT_INVALID_ARGUMENT(load(names + "models: {psi: {time_constant: 0.1}}\n"), "psi");
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
