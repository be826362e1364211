// config/norma.yaml and config/rotor.yaml: each read through YamlParameterSource equals the
// code's defaults (those sphere_sim norma and rotor-execute used before the files existed) to the
// bit; the launch files' arguments that override them default to their values; absent keys keep
// the defaults, present ones override them; a bad value is named with its key, value and file.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <tuple>

#include "spherical_robots/config/norma_config.hpp"
#include "spherical_robots/config/rotor_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"
#include "spherical_robots/norma/sampled_norma_loop.hpp"
#include "spherical_robots/rotor/sampled_rotor_loop.hpp"
#include "expect_invalid_argument.hpp"
#include "temp_yaml.hpp"

namespace {

// CMakeLists.txt defines SPHERICAL_ROBOTS_SOURCE_DIR: the shipped files of the source tree.
const std::string kSource = SPHERICAL_ROBOTS_SOURCE_DIR;
const std::string kNorma = kSource + "/config/norma.yaml";
const std::string kRotor = kSource + "/config/rotor.yaml";

namespace config = spherical_robots::config;
namespace norma = spherical_robots::norma;
namespace rotor = spherical_robots::rotor;
using config::YamlParameterSource;
using spherical_robots::test_support::TempYaml;

/// Every <arg name="..." default="..."/> of a launch file.
std::map<std::string, std::string> launchDefaults(const std::string& launch) {
  std::ifstream file(kSource + "/launch/" + launch);
  std::stringstream text;
  text << file.rdbuf();
  const std::string xml = text.str();
  std::map<std::string, std::string> defaults;
  const std::regex arg(R"re(<arg\s+name="([^"]+)"\s+default="([^"]*)")re");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), arg); it != std::sregex_iterator();
       ++it)
    defaults[(*it)[1]] = (*it)[2];
  return defaults;
}

auto pid(const norma::PidGains& g) { return std::make_tuple(g.kp, g.ki, g.kd); }

auto everyField(const norma::ControllerGains& g) {
  return std::make_tuple(g.kinematic.k1, g.kinematic.k2, g.kinematic.k3, pid(g.rate),
                         pid(g.pendulum), pid(g.slider), g.along_gain, g.cross_gain,
                         g.heading_gain, g.tilt_gain, g.tilt_damping, g.max_slider,
                         pid(g.tracking_slider));
}

auto everyField(const rotor::ManoeuvreExecutive::Parameters& e) {
  return std::make_tuple(e.radius, e.inertia_scale, e.curve_rate, e.ramp_time, e.command_period,
                         e.max_rotor_speed, e.settle, e.actuator_time_constant, e.corrections,
                         e.correction_tolerance, e.correction_heading_tolerance,
                         e.correction_tilt_tolerance, e.correction_steps, e.max_clock_step);
}

TEST(NormaConfig, ShippedFileEqualsTheDefaultsToTheBit) {
  const YamlParameterSource source(kNorma);
  const config::NormaModelParameters model =
      config::normaModelParameters(source, config::kNormaPlantKeys);
  EXPECT_EQ(model.variant, norma::LagrangianVariant::kText);
  EXPECT_EQ(model.variant, norma::ClosedLoopConfig().variant);
  // psi(0) along eq 52's initial velocity: the sampled loop's (and so sphere_sim's) default.
  EXPECT_EQ(model.initial_psi, norma::pathStartHeading());
  EXPECT_EQ(model.initial_psi, norma::SampledLoopConfig().initial_psi);
  const config::NormaControlParameters control =
      config::normaControlParameters(source, config::kNormaControllerKeys);
  EXPECT_EQ(control.controller, norma::ControllerKind::kPaper);
  EXPECT_EQ(control.controller, norma::ClosedLoopConfig().controller);
  EXPECT_EQ(control.limits.max_torque, norma::EffortLimits().max_torque);
  EXPECT_EQ(control.limits.max_force, norma::EffortLimits().max_force);
  EXPECT_EQ(everyField(control.gains), everyField(norma::ControllerGains()));
  EXPECT_EQ(everyField(control.gains), everyField(norma::ClosedLoopConfig().gains));
  EXPECT_EQ(everyField(control.gains), everyField(norma::SampledLoopConfig().gains));
}

TEST(NormaConfig, LaunchArgumentsDefaultToTheFile) {
  std::map<std::string, std::string> args = launchDefaults("norma_stack.launch");
  const YamlParameterSource source(kNorma);
  EXPECT_EQ(args["variant"], *source.text("norma_plant/variant"));
  EXPECT_EQ(args["controller"], *source.text("norma_controller/controller"));
  EXPECT_EQ(std::stod(args["max_torque"]), *source.number("norma_controller/max_torque"));
  EXPECT_EQ(std::stod(args["max_force"]), *source.number("norma_controller/max_force"));
}

TEST(NormaConfig, AbsentKeysKeepTheDefaultsPresentOnesOverride) {
  const TempYaml file("norma_plant: {variant: appendix}\nnorma_controller: {max_force: 50.0}\n");
  const YamlParameterSource source(file.path());
  const auto model = config::normaModelParameters(source, config::kNormaPlantKeys);
  EXPECT_EQ(model.variant, norma::LagrangianVariant::kAppendix);
  EXPECT_EQ(model.initial_psi, 0.0);
  const auto control = config::normaControlParameters(source, config::kNormaControllerKeys);
  EXPECT_EQ(control.controller, norma::ControllerKind::kPaper);
  EXPECT_EQ(control.limits.max_torque, 20.0);
  EXPECT_EQ(control.limits.max_force, 50.0);
  EXPECT_EQ(everyField(control.gains), everyField(norma::ControllerGains()));
  const TempYaml gains("norma_controller: {gains: {pendulum: {kd: 4.0}, tilt_gain: 0.1}}\n");
  const auto tuned = config::normaControlParameters(YamlParameterSource(gains.path()),
                                                    config::kNormaControllerKeys);
  EXPECT_EQ(tuned.gains.pendulum.kd, 4.0);
  EXPECT_EQ(tuned.gains.pendulum.kp, 10.0);
  EXPECT_EQ(tuned.gains.tilt_gain, 0.1);
}

TEST(NormaConfig, BadValuesNameTheKeyTheValueAndTheFile) {
  const TempYaml variant("norma_plant: {variant: textt}\n");
  EXPECT_INVALID_ARGUMENT(
      config::normaModelParameters(YamlParameterSource(variant.path()), config::kNormaPlantKeys),
      "norma_plant/variant", "textt", variant.path());
  const TempYaml psi("norma_plant: {initial_psi: .inf}\n");
  EXPECT_INVALID_ARGUMENT(
      config::normaModelParameters(YamlParameterSource(psi.path()), config::kNormaPlantKeys),
      "norma_plant/initial_psi", "finite", psi.path());
  const TempYaml torque("norma_controller: {max_torque: -1.0}\n");
  EXPECT_INVALID_ARGUMENT(config::normaControlParameters(YamlParameterSource(torque.path()),
                                                         config::kNormaControllerKeys),
                          "norma_controller/max_torque", "-1", "> 0", torque.path());
  const TempYaml controller("norma_controller: {controller: pid}\n");
  EXPECT_INVALID_ARGUMENT(config::normaControlParameters(YamlParameterSource(controller.path()),
                                                         config::kNormaControllerKeys),
                          "norma_controller/controller", "pid", controller.path());
  const TempYaml k3("norma_controller: {gains: {kinematic: {k3: nope}}}\n");
  EXPECT_INVALID_ARGUMENT(config::normaControlParameters(YamlParameterSource(k3.path()),
                                                         config::kNormaControllerKeys),
                          "norma_controller/gains/kinematic/k3", "nope", k3.path());
  const TempYaml rate_kd("norma_controller: {gains: {rate: {kd: 1.0}}}\n");
  EXPECT_INVALID_ARGUMENT(config::normaControlParameters(YamlParameterSource(rate_kd.path()),
                                                         config::kNormaControllerKeys),
                          "norma_controller/gains/", "PID1 kd must be 0", rate_kd.path());
}

TEST(RotorConfig, ShippedFileEqualsTheDefaultsToTheBit) {
  const YamlParameterSource source(kRotor);
  // The executive's defaults, but the rotor limit the stack has always set (and sphere_sim's
  // --max-rotor-speed default): 25 rad/s.
  rotor::ManoeuvreExecutive::Parameters expected;
  expected.max_rotor_speed = 25.0;
  EXPECT_EQ(everyField(config::rotorExecutiveParameters(source, source, config::kRotorPlannerKeys)),
            everyField(expected));
  EXPECT_EQ(*source.number("inertia_ratio"), rotor::RotorStackSampling().k);
  EXPECT_EQ(*source.number("rotor_plant/sphere_radius"), expected.radius);
  const config::RotorManoeuvre m = config::rotorManoeuvre(source, "manoeuvre/");
  EXPECT_EQ(std::make_tuple(m.k, m.steps, m.u, m.v, m.psi),
            std::make_tuple(2.5, 2, 0.05, 0.03, 0.4));
}

TEST(RotorConfig, LaunchArgumentsDefaultToTheFile) {
  std::map<std::string, std::string> args = launchDefaults("rotor_stack.launch");
  const YamlParameterSource source(kRotor);
  EXPECT_EQ(std::stod(args["k"]), *source.number("inertia_ratio"));
  EXPECT_EQ(std::stod(args["k"]), *source.number("manoeuvre/k"));
  EXPECT_EQ(std::stod(args["steps"]), *source.number("manoeuvre/steps"));
  std::istringstream target(args["target"]);
  for (const char* key : {"manoeuvre/u", "manoeuvre/v", "manoeuvre/psi"}) {
    std::string number;
    std::getline(target, number, ',');
    EXPECT_EQ(std::stod(number), *source.number(key)) << key;
  }
  for (const char* name : {"curve_rate", "actuator_time_constant", "corrections",
                           "correction_tolerance", "correction_tilt_tolerance"})
    EXPECT_EQ(std::stod(args[name]), *source.number(config::kRotorPlannerKeys + name)) << name;
}

TEST(RotorConfig, AbsentKeysKeepTheDefaultsPresentOnesOverride) {
  const TempYaml file("rotor_inertia_scale: 10.0\nrotor_planner: {corrections: 2}\n"
                      "manoeuvre: {steps: 3}\n");
  const YamlParameterSource source(file.path());
  const auto e = config::rotorExecutiveParameters(source, source, config::kRotorPlannerKeys);
  EXPECT_EQ(e.inertia_scale, 10.0);
  EXPECT_EQ(e.corrections, 2);
  EXPECT_EQ(e.curve_rate, rotor::ManoeuvreExecutive::Parameters().curve_rate);
  EXPECT_EQ(e.max_rotor_speed, 0.0);
  const auto m = config::rotorManoeuvre(source, "manoeuvre/");
  EXPECT_EQ(m.steps, 3);
  EXPECT_EQ(m.k, 2.5);
}

TEST(RotorConfig, BadValuesNameTheKeyTheValueAndTheFile) {
  const struct {
    std::string yaml;
    std::vector<std::string> needles;
  } cases[] = {
      {"rotor_planner: {corrections: 1.5}", {"rotor_planner/corrections", "1.5", "integer >= 0"}},
      {"rotor_planner: {curve_rate: 0.0}", {"rotor_planner/curve_rate", "> 0"}},
      {"rotor_planner: {settle: -1.0}", {"rotor_planner/settle", "-1", ">= 0"}},
      {"rotor_planner: {command_rate: fast}", {"rotor_planner/command_rate", "fast"}},
      {"rotor_inertia_scale: -12.0", {"rotor_inertia_scale", "-12", "> 0"}},
  };
  for (const auto& c : cases) {
    const TempYaml file(c.yaml + "\n");
    const YamlParameterSource source(file.path());
    for (const std::string& needle : c.needles)
      EXPECT_INVALID_ARGUMENT(
          config::rotorExecutiveParameters(source, source, config::kRotorPlannerKeys), needle,
          file.path());
  }
  const TempYaml steps("manoeuvre: {steps: 0}\n");
  EXPECT_INVALID_ARGUMENT(config::rotorManoeuvre(YamlParameterSource(steps.path()), "manoeuvre/"),
                          "manoeuvre/steps", "integer >= 1", steps.path());
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
