// Each node's parameter loader (and the plant loop's) read from YAML, as the nodes read them from
// the parameter server: the defaults docs/nodes.md gives, a few overrides, and a clear error
// naming the key, the value and the limit for each malformed parameter. No ROS master.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/HardwareInterfaceSimConfig.h"
#include "spherical_robots/config/hardware_interface_config.hpp"
#include "spherical_robots/config/odometry_parameters.hpp"
#include "spherical_robots/config/plant_loop_parameters.hpp"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "spherical_robots/ros/freebot_ik_ros.hpp"
#include "spherical_robots/ros/friction_drive_controller_ros.hpp"
#include "spherical_robots/ros/friction_drive_sim_ros.hpp"
#include "spherical_robots/ros/norma_controller_ros.hpp"
#include "spherical_robots/ros/norma_plant_ros.hpp"
#include "spherical_robots/ros/pure_pursuit_controller_ros.hpp"
#include "spherical_robots/ros/rotor_planner_parameters.hpp"
#include "spherical_robots/ros/rotor_plant_ros.hpp"
#include "spherical_robots/ros/terrain_plant_ros.hpp"
#include "temp_yaml.hpp"

namespace config = spherical_robots::config;
namespace sr = spherical_robots;
using spherical_robots::LoopCpuSetting;
using spherical_robots::test_support::TempYaml;

namespace {

/// load(source) of a YAML file holding text ("{}" for none).
template <typename Load>
auto fromYaml(const std::string& text, Load load) {
  const TempYaml file(text);
  return load(config::YamlParameterSource(file.path()));
}

/// load(source) of a YAML file holding text, each of the source's warnings appended to warnings.
template <typename Load>
auto fromYaml(const std::string& text, Load load, std::vector<std::string>& warnings) {
  const TempYaml file(text);
  return load(config::YamlParameterSource(
      file.path(), [&warnings](const std::string& message) { warnings.push_back(message); }));
}

config::PlantLoopParameters loop(const std::string& text) {
  config::PlantLoopParameters defaults;
  defaults.step = 0.001;
  defaults.speedup = 10.0;
  defaults.trail_period = 0.5;
  return fromYaml(text, [&](const config::ParameterSource& s) {
    return config::loadPlantLoopParameters(s, defaults);
  });
}

}  // namespace

TEST(PlantLoopParameters, DefaultsAreThePlantsAndTheDocumentedOnes) {
  const auto p = loop("{}");
  EXPECT_EQ(p.step, 0.001);
  EXPECT_EQ(p.publish_rate, 50.0);
  EXPECT_EQ(p.state_timeout, 0.5);
  EXPECT_EQ(p.trail_period, 0.5);
  EXPECT_EQ(p.duration, 0.0);
  EXPECT_EQ(p.max_clock_step, 5.0);
  EXPECT_EQ(p.clock, config::ClockMode::kRos);
  EXPECT_EQ(p.wait_for_subscribers, 1);
  EXPECT_EQ(p.start_timeout, 10.0);
}

TEST(PlantLoopParameters, SpeedupDependsOnTheClock) {
  EXPECT_EQ(loop("clock: lockstep\n").speedup, 0.0);
  EXPECT_EQ(loop("clock: free\n").speedup, 10.0);
  EXPECT_EQ(loop("clock: free\nspeedup: 2\n").speedup, 2.0);
  const auto lockstep = loop("clock: lockstep\nspeedup: 1\nlockstep_leader: /sphere\n");
  EXPECT_EQ(lockstep.speedup, 1.0);
  EXPECT_EQ(lockstep.lockstep_leader, "/sphere");
  EXPECT_EQ(lockstep.lockstep_timeout, 1.0);  // a follower drops its own participant first
  EXPECT_EQ(loop("clock: lockstep\n").lockstep_timeout, 2.0);
  EXPECT_EQ(loop("step: 0.01\nduration: 20\nwait_for_subscribers: 2\n").wait_for_subscribers, 2);
}

TEST(PlantLoopParameters, MalformedParametersAreNamed) {
  EXPECT_INVALID_ARGUMENT(loop("clock: sometimes\n"), "clock", "sometimes", "lockstep | free | ros");
  EXPECT_INVALID_ARGUMENT(loop("step: 0\n"), "step", "> 0");
  EXPECT_INVALID_ARGUMENT(loop("clock: free\nspeedup: 0\n"), "speedup", "> 0");
  EXPECT_INVALID_ARGUMENT(loop("clock: lockstep\nspeedup: -1\n"), "speedup", ">= 0");
  EXPECT_INVALID_ARGUMENT(loop("clock: lockstep\nlockstep_leader: sphere\n"), "lockstep_leader",
                          "absolute namespace");
  EXPECT_INVALID_ARGUMENT(loop("wait_for_subscribers: 1.5\n"), "wait_for_subscribers", "1.5",
                          "integer >= 0");
  EXPECT_INVALID_ARGUMENT(loop("duration: .nan\n"), "duration", "finite");
  EXPECT_INVALID_ARGUMENT(loop("publish_rate: fast\n"), "publish_rate", "number");
  EXPECT_INVALID_ARGUMENT(loop("checkpoint: checkpoints\n"), "checkpoint", "checkpoints",
                          "none, ros_home or an absolute directory");
  EXPECT_INVALID_ARGUMENT(loop("clock: lockstep\nloop_cpu: fast\n"), "loop_cpu", "fast",
                          "auto, none or a CPU number");
  EXPECT_INVALID_ARGUMENT(loop("clock: lockstep\nloop_cpu: -1\n"), "loop_cpu", "-1", ">= 0");
  EXPECT_INVALID_ARGUMENT(loop("clock: lockstep\nloop_cpu: 0.5\n"), "loop_cpu", "0.5", "integer");
}

TEST(PlantLoopParameters, LoopCpuIsAutoByDefaultAWordOrANumber) {
  using Kind = LoopCpuSetting::Kind;
  EXPECT_EQ(loop("clock: lockstep\n").loop_cpu.kind, Kind::kAuto);
  EXPECT_EQ(loop("clock: lockstep\nloop_cpu: none\n").loop_cpu.kind, Kind::kNone);
  const auto fixed = loop("clock: lockstep\nloop_cpu: 1\n").loop_cpu;
  EXPECT_EQ(fixed.kind, Kind::kFixed);
  EXPECT_EQ(fixed.cpu, 1);
  EXPECT_EQ(loop("clock: lockstep\nloop_cpu: '3'\n").loop_cpu.cpu, 3);
}

TEST(PlantLoopParameters, CheckpointNoneByDefault) {
  EXPECT_EQ(loop("").checkpoint, "none");
  EXPECT_EQ(loop("checkpoint: ros_home\n").checkpoint, "ros_home");
  EXPECT_EQ(loop("checkpoint: /var/tmp/plants\n").checkpoint, "/var/tmp/plants");
}

TEST(TerrainPlantParameters, DefaultsOverridesAndErrors) {
  const auto p = fromYaml("{}", sr::loadTerrainPlantParameters);
  EXPECT_EQ(p.robot_type, sr::terrain::RobotType::ThreeAxisRolling);
  EXPECT_EQ(p.contact_model, sr::terrain::ContactModel::Paper);
  EXPECT_EQ(p.frame_prefix, "");
  EXPECT_EQ(p.max_actuator_rate, 1000.0);
  EXPECT_EQ(p.marker_half_extent, 3.0);
  EXPECT_EQ(p.marker_resolution, 0.1);
  const auto q = fromYaml("robot_type: RS\ncontact_model: rolling\nframe_prefix: a/\ninitial_x: -1\n",
                          sr::loadTerrainPlantParameters);
  EXPECT_EQ(q.robot_type, sr::terrain::RobotType::RollingAndSteering);
  EXPECT_EQ(q.contact_model, sr::terrain::ContactModel::Rolling);
  EXPECT_EQ(q.frame_prefix, "a/");
  EXPECT_EQ(q.initial_x, -1.0);
  EXPECT_INVALID_ARGUMENT(fromYaml("robot_type: 4R\n", sr::loadTerrainPlantParameters),
                          "robot_type", "4R");
  EXPECT_INVALID_ARGUMENT(fromYaml("marker_resolution: 0\n", sr::loadTerrainPlantParameters),
                          "marker_resolution", "> 0");
  EXPECT_INVALID_ARGUMENT(fromYaml("initial_psi: .inf\n", sr::loadTerrainPlantParameters),
                          "initial_psi", "finite");
}

TEST(PlantLoopParameters, OriginOfTheRootFrameInMap) {
  const auto p = loop("{}");
  EXPECT_EQ(p.origin_x, 0.0);
  EXPECT_EQ(p.origin_y, 0.0);
  EXPECT_EQ(p.origin_yaw, 0.0);
  const auto q = loop("origin_x: 2.5\norigin_y: -1\norigin_yaw: 1.5\n");
  EXPECT_EQ(q.origin_x, 2.5);
  EXPECT_EQ(q.origin_y, -1.0);
  EXPECT_EQ(q.origin_yaw, 1.5);
  EXPECT_INVALID_ARGUMENT(loop("origin_y: .nan\n"), "origin_y", "finite");
}

// docs/nodes.md, "Odometry and IMU": the covariance floor, the noise off and no IMU by default;
// with noise, the default covariances are the floor plus the noise's variance.
TEST(OdometryParameters, DefaultsNoiseAndCovariances) {
  const auto p = fromYaml("{}", config::loadOdometryParameters);
  for (double v : p.pose_covariance_diagonal) EXPECT_EQ(v, 1e-6);
  for (double v : p.twist_covariance_diagonal) EXPECT_EQ(v, 1e-6);
  EXPECT_EQ(p.noise.position, 0.0);
  EXPECT_EQ(p.noise.yaw, 0.0);
  EXPECT_EQ(p.noise.linear_velocity, 0.0);
  EXPECT_EQ(p.noise.angular_velocity, 0.0);
  EXPECT_EQ(p.noise.linear_acceleration, 0.0);
  EXPECT_EQ(p.imu_rate, 0.0);
  const auto q = fromYaml(
      "noise: {position: 0.01, yaw: 0.02, linear_velocity: 0.03, angular_velocity: 0.04, "
      "linear_acceleration: 0.5, seed: 7}\nimu_rate: 100\n",
      config::loadOdometryParameters);
  EXPECT_EQ(q.noise.seed, 7u);
  EXPECT_EQ(q.imu_rate, 100.0);
  EXPECT_DOUBLE_EQ(q.pose_covariance_diagonal[0], 1e-6 + 1e-4);
  EXPECT_DOUBLE_EQ(q.pose_covariance_diagonal[2], 1e-6 + 1e-4);
  EXPECT_EQ(q.pose_covariance_diagonal[3], 1e-6);  // roll: no noise
  EXPECT_DOUBLE_EQ(q.pose_covariance_diagonal[5], 1e-6 + 4e-4);
  EXPECT_DOUBLE_EQ(q.twist_covariance_diagonal[1], 1e-6 + 9e-4);
  EXPECT_DOUBLE_EQ(q.twist_covariance_diagonal[5], 1e-6 + 16e-4);
  EXPECT_DOUBLE_EQ(q.imu_linear_acceleration_covariance_diagonal[2], 1e-6 + 0.25);
  const auto r = fromYaml("pose_covariance_diagonal: [1, 2, 3, 4, 5, 6]\n", config::loadOdometryParameters);
  EXPECT_EQ(r.pose_covariance_diagonal[4], 5.0);
  EXPECT_INVALID_ARGUMENT(fromYaml("pose_covariance_diagonal: [1, 2, 3]\n", config::loadOdometryParameters),
                          "pose_covariance_diagonal", "3 entries", "expected 6");
  EXPECT_INVALID_ARGUMENT(
      fromYaml("twist_covariance_diagonal: [1, 2, 3, -4, 5, 6]\n", config::loadOdometryParameters),
      "twist_covariance_diagonal", "entry 3", "-4");
  EXPECT_INVALID_ARGUMENT(fromYaml("noise: {yaw: -0.1}\n", config::loadOdometryParameters), "noise/yaw",
                          ">= 0");
  EXPECT_INVALID_ARGUMENT(fromYaml("noise: {seed: 1.5}\n", config::loadOdometryParameters), "noise/seed");
  EXPECT_INVALID_ARGUMENT(fromYaml("imu_rate: -1\n", config::loadOdometryParameters), "imu_rate");
}

TEST(PurePursuitControllerParameters, DefaultsOverridesAndErrors) {
  using P = sr::PurePursuitControllerParameters;
  const auto p = fromYaml("{}", sr::loadPurePursuitControllerParameters);
  EXPECT_EQ(p.mode, P::Mode::Tracking);
  EXPECT_EQ(p.law, sr::terrain::PursuitLaw::Smooth);
  EXPECT_EQ(p.path, "circle");
  EXPECT_EQ(p.rate, 50.0);
  EXPECT_EQ(p.state_timeout, 0.5);
  EXPECT_EQ(p.cmd_vel_timeout, 0.5);
  EXPECT_EQ(p.max_position, 1e3);
  EXPECT_EQ(p.max_cmd_vel, 10.0);
  EXPECT_EQ(p.max_stamp_skew, 1.0);
  EXPECT_EQ(p.max_clock_step, 5.0);
  EXPECT_EQ(p.teleop_tilt_gain, 2.0);
  EXPECT_EQ(p.untimed_speed, 0.1);
  EXPECT_EQ(p.path_tf_timeout, 1.0);
  EXPECT_EQ(p.odom_frame, "odom");
  const auto q = fromYaml("mode: teleop\nlaw: paper\nrobot_type: 2R\nrate: 100\n"
                          "path: topic\nuntimed_speed: 0.25\n",
                          sr::loadPurePursuitControllerParameters);
  EXPECT_EQ(q.mode, P::Mode::Teleop);
  EXPECT_EQ(q.law, sr::terrain::PursuitLaw::Paper);
  EXPECT_EQ(q.robot_type, sr::terrain::RobotType::TwoAxisRolling);
  EXPECT_EQ(q.rate, 100.0);
  EXPECT_EQ(q.path, P::kPathFromTopic);
  EXPECT_EQ(q.untimed_speed, 0.25);
  EXPECT_INVALID_ARGUMENT(fromYaml("untimed_speed: 0\n", sr::loadPurePursuitControllerParameters),
                          "untimed_speed", "> 0");
  // config/terrain.yaml, loaded into the stack's namespace, gives the node its documented default.
  EXPECT_EQ(config::YamlParameterSource(SPHERICAL_ROBOTS_SOURCE_DIR "/config/terrain.yaml")
                .number("pure_pursuit_controller/untimed_speed"),
            P{}.untimed_speed);
  EXPECT_INVALID_ARGUMENT(fromYaml("mode: drive\n", sr::loadPurePursuitControllerParameters),
                          "mode", "drive", "tracking | teleop");
  EXPECT_INVALID_ARGUMENT(fromYaml("law: fast\n", sr::loadPurePursuitControllerParameters),
                          "law", "fast");
  EXPECT_INVALID_ARGUMENT(fromYaml("state_timeout: -1\n", sr::loadPurePursuitControllerParameters),
                          "state_timeout", "-1", "> 0");
  EXPECT_INVALID_ARGUMENT(fromYaml("cmd_vel_timeout: 0\n", sr::loadPurePursuitControllerParameters),
                          "cmd_vel_timeout", "0", "> 0");
}

TEST(NormaParameters, DefaultsOverridesAndErrors) {
  const auto plant = fromYaml("{}", sr::loadNormaPlantParameters);
  EXPECT_EQ(plant.variant, sr::norma::LagrangianVariant::kText);
  EXPECT_EQ(plant.max_actuator_effort, 1e4);
  EXPECT_EQ(plant.initial_psi, 0.0);
  EXPECT_EQ(fromYaml("variant: appendix\n", sr::loadNormaPlantParameters).variant,
            sr::norma::LagrangianVariant::kAppendix);
  EXPECT_INVALID_ARGUMENT(fromYaml("variant: text2\n", sr::loadNormaPlantParameters), "variant",
                          "text2");
  const auto controller = fromYaml("{}", sr::loadNormaControllerParameters);
  EXPECT_EQ(controller.controller, sr::norma::ControllerKind::kPaper);
  EXPECT_EQ(controller.limits.max_torque, 20.0);
  EXPECT_EQ(controller.limits.max_force, 200.0);
  EXPECT_EQ(controller.publish_rate, 50.0);
  EXPECT_EQ(controller.max_stamp_skew, 1.0);
  EXPECT_EQ(controller.state_timeout, 0.05);
  const auto tracking =
      fromYaml("controller: tracking\nmax_torque: 5\n", sr::loadNormaControllerParameters);
  EXPECT_EQ(tracking.controller, sr::norma::ControllerKind::kTracking);
  EXPECT_EQ(tracking.limits.max_torque, 5.0);
  EXPECT_INVALID_ARGUMENT(fromYaml("max_force: 0\n", sr::loadNormaControllerParameters),
                          "max_force", "> 0");
  EXPECT_INVALID_ARGUMENT(fromYaml("controller: pid\n", sr::loadNormaControllerParameters),
                          "controller", "pid");
}

TEST(RotorParameters, DefaultsOverridesAndErrors) {
  const TempYaml stack("inertia_ratio: 3\n");
  const TempYaml node("{}\n");
  const config::YamlParameterSource stack_source(stack.path()), node_source(node.path());
  const auto plant = sr::loadRotorPlantParameters(stack_source, node_source);
  EXPECT_EQ(plant.inertia_ratio, 3.0);
  EXPECT_EQ(plant.rotor_inertia_scale, 12.0);
  EXPECT_EQ(plant.sphere_radius, 0.1);
  const auto planner = sr::loadRotorPlannerParameters(stack_source, node_source);
  ASSERT_TRUE(planner.robot_inertia_ratio);
  EXPECT_EQ(*planner.robot_inertia_ratio, 3.0);
  EXPECT_FALSE(planner.manoeuvre);
  EXPECT_EQ(planner.max_radius, 0.7 * planner.executive.radius);  // 0.7 R
  const TempYaml manoeuvre("manoeuvre: {k: 2.5, steps: 3}\nmax_rotor_speed: 25\n");
  const auto executing =
      sr::loadRotorPlannerParameters(node_source, config::YamlParameterSource(manoeuvre.path()));
  ASSERT_TRUE(executing.manoeuvre);
  EXPECT_EQ(executing.manoeuvre->steps, 3);
  EXPECT_EQ(executing.executive.max_rotor_speed, 25.0);
  EXPECT_FALSE(executing.robot_inertia_ratio);
  const auto planner_with = [&](const std::string& text) {
    return fromYaml(text, [&](const config::ParameterSource& s) {
      return sr::loadRotorPlannerParameters(node_source, s);
    });
  };
  EXPECT_INVALID_ARGUMENT(planner_with("max_radius: 0.08\n"), "max_radius", "0.08", "R / sqrt(2)");
  EXPECT_INVALID_ARGUMENT(planner_with("ramp_time: -1\n"), "ramp_time", ">= 0");
  EXPECT_INVALID_ARGUMENT(planner_with("manoeuvre: {steps: 0}\n"), "manoeuvre/steps", "integer >= 1");
  EXPECT_INVALID_ARGUMENT(fromYaml("rotor_inertia_scale: 0\n", [&](const config::ParameterSource& s) {
                            return sr::loadRotorPlantParameters(s, node_source);
                          }),
                          "rotor_inertia_scale", "> 0");
}

TEST(FrictionDriveParameters, DefaultsOverridesAndErrors) {
  const auto controller = fromYaml("{}", sr::loadFrictionDriveControllerParameters);
  EXPECT_EQ(controller.max_actuator_rate, 1000.0);
  EXPECT_EQ(controller.command_timeout, 0.5);
  const auto sim = fromYaml("marker_rate: 5\nframe_prefix: roller/\n", sr::loadFrictionDriveSimParameters);
  EXPECT_EQ(sim.marker_rate, 5.0);
  EXPECT_EQ(sim.frame_prefix, "roller/");
  EXPECT_EQ(sim.state_timeout, 0.5);
  EXPECT_INVALID_ARGUMENT(fromYaml("marker_rate: 0\n", sr::loadFrictionDriveSimParameters),
                          "marker_rate", "> 0");
  EXPECT_INVALID_ARGUMENT(fromYaml("command_timeout: x\n", sr::loadFrictionDriveControllerParameters),
                          "command_timeout", "number");
}

// The rule for a renamed parameter, once for every node (config::renamedNumber): the new name
// wins, the old one still works for a release, and either way a set old name is reported once.
TEST(RenamedParameters, NewNameWinsOldNameWorksWithOneWarning) {
  const config::RenamedKey name{"state_timeout", "input_timeout"};
  const auto read = [&](const config::ParameterSource& s) {
    return config::renamedNumber(s, name, 0.5, config::positiveNumber);
  };
  std::vector<std::string> warnings;
  EXPECT_EQ(fromYaml("{}", read, warnings), 0.5);
  EXPECT_EQ(fromYaml("state_timeout: 0.2\n", read, warnings), 0.2);
  EXPECT_TRUE(warnings.empty());

  EXPECT_EQ(fromYaml("input_timeout: 0.3\n", read, warnings), 0.3);
  ASSERT_EQ(warnings.size(), 1u);
  for (const char* part : {"'input_timeout' is deprecated", "renamed 'state_timeout'",
                           "state_timeout = 0.3", "docs/migration.md"})
    EXPECT_NE(warnings[0].find(part), std::string::npos) << part << " not in: " << warnings[0];

  warnings.clear();
  EXPECT_EQ(fromYaml("input_timeout: 0.3\nstate_timeout: 0.2\n", read, warnings), 0.2);
  ASSERT_EQ(warnings.size(), 1u);
  for (const char* part : {"'input_timeout' is deprecated", "both are set", "state_timeout = 0.2",
                           "ignoring input_timeout"})
    EXPECT_NE(warnings[0].find(part), std::string::npos) << part << " not in: " << warnings[0];

  // A bad value is named by the name the user wrote; the new name's wins even over a bad old one.
  EXPECT_INVALID_ARGUMENT(fromYaml("input_timeout: -1\n", read, warnings), "input_timeout", "-1",
                          "> 0");
  EXPECT_INVALID_ARGUMENT(fromYaml("input_timeout: 1\nstate_timeout: 0\n", read, warnings),
                          "state_timeout", "> 0");
  EXPECT_EQ(fromYaml("input_timeout: x\nstate_timeout: 0.2\n", read, warnings), 0.2);
}

// Each node's timeout that was ~input_timeout up to 0.2.0 (docs/migration.md): the old name
// still sets it, with one warning per new name it sets.
TEST(RenamedParameters, EveryNodeStillReadsInputTimeout) {
  const std::string old_name = "input_timeout: 0.25\n";
  std::vector<std::string> warnings;
  const auto pursuit = fromYaml(old_name, sr::loadPurePursuitControllerParameters, warnings);
  EXPECT_EQ(pursuit.state_timeout, 0.25);
  EXPECT_EQ(pursuit.cmd_vel_timeout, 0.25);
  EXPECT_EQ(warnings.size(), 2u);
  const auto pursuit_new = fromYaml(old_name + "cmd_vel_timeout: 0.1\n",
                                    sr::loadPurePursuitControllerParameters, warnings);
  EXPECT_EQ(pursuit_new.state_timeout, 0.25);
  EXPECT_EQ(pursuit_new.cmd_vel_timeout, 0.1);

  warnings.clear();
  EXPECT_EQ(fromYaml(old_name, sr::loadNormaControllerParameters, warnings).state_timeout, 0.25);
  EXPECT_EQ(fromYaml(old_name, sr::loadFrictionDriveControllerParameters, warnings).command_timeout,
            0.25);
  EXPECT_EQ(fromYaml(old_name, sr::loadFrictionDriveSimParameters, warnings).state_timeout, 0.25);
  const config::YamlParameterSource freebot(SPHERICAL_ROBOTS_SOURCE_DIR "/config/freebot.yaml");
  const auto ik = fromYaml(
      old_name,
      [&](const config::ParameterSource& node) { return sr::loadFreebotIkParameters(freebot, node); },
      warnings);
  EXPECT_EQ(ik.state_timeout, 0.25);
  EXPECT_EQ(warnings.size(), 4u);
  EXPECT_EQ(fromYaml("{}", [&](const config::ParameterSource& node) {
              return sr::loadFreebotIkParameters(freebot, node);
            }).state_timeout, 0.1);
}

// dynamic_reconfigure writes its .cfg defaults to the parameter server when a parameter is unset:
// they must be the loader's, or starting the reconfigure server would change the node's limits.
TEST(Reconfigure, HardwareInterfaceSimDefaultsAreTheLoaders) {
  const config::HardwareInterfaceSimParameters loaded = fromYaml(
      "actuator_names: [theta]", config::loadHardwareInterfaceSimParameters);
  const auto& defaults = spherical_robots::HardwareInterfaceSimConfig::__getDefault__();
  EXPECT_EQ(defaults.max_velocity, loaded.limits.front().max_velocity);
  EXPECT_EQ(defaults.max_acceleration, loaded.limits.front().max_acceleration);
  EXPECT_EQ(defaults.command_timeout, loaded.command_timeout);
}

// The .cfg's defaults are the core's ControllerGains (what a reset in rqt_reconfigure gives), and
// every gain goes through the node's table both ways: distinct values survive the round trip.
TEST(Reconfigure, NormaControllerDefaultsAreTheCoresAndEveryGainRoundTrips) {
  using Config = spherical_robots::NormaControllerConfig;
  const Config from_core = sr::reconfigureConfigOf(spherical_robots::norma::ControllerGains());
  const Config& defaults = Config::__getDefault__();
  int compared = 0;
  for (const auto& param : Config::__getParamDescriptions__()) {
    boost::any core_value, cfg_value;
    param->getValue(from_core, core_value);
    param->getValue(defaults, cfg_value);
    EXPECT_EQ(boost::any_cast<double>(core_value), boost::any_cast<double>(cfg_value)) << param->name;
    ++compared;
  }
  EXPECT_EQ(compared, 20);

  spherical_robots::norma::ControllerGains distinct;
  dynamic_reconfigure::Config message;
  double next = 1.0;
  for (const auto& param : Config::__getParamDescriptions__()) {
    dynamic_reconfigure::DoubleParameter value;
    value.name = param->name;
    value.value = next++;
    message.doubles.push_back(value);
  }
  Config numbered = defaults;
  ASSERT_TRUE(numbered.__fromMessage__(message));
  distinct = sr::gainsOf(numbered, distinct);
  const Config back = sr::reconfigureConfigOf(distinct);
  for (const auto& param : Config::__getParamDescriptions__()) {
    boost::any a, b;
    param->getValue(numbered, a);
    param->getValue(back, b);
    EXPECT_EQ(boost::any_cast<double>(a), boost::any_cast<double>(b)) << param->name;
  }
  EXPECT_EQ(distinct.rate.kd, 0.0);  // not reconfigurable: PID1 has no derivative term
}

namespace {

using PursuitConfig = spherical_robots::PurePursuitControllerConfig;

/// The .cfg's numbers of config, by name.
std::vector<std::pair<std::string, double>> doublesOf(const PursuitConfig& config) {
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  std::vector<std::pair<std::string, double>> doubles;
  for (const auto& field : message.doubles) doubles.emplace_back(field.name, field.value);
  return doubles;
}

}  // namespace

// cfg/PurePursuitController.cfg names the gains as config/terrain.yaml does, in the same order,
// and its defaults are the core's for 3R (what a reset in rqt_reconfigure gives) with the node's
// default law: the names live in the .cfg and in config::namedPursuitGains, and this keeps them
// in step.
TEST(Reconfigure, PursuitControllerNamesAndDefaultsAreTheCores) {
  using sr::terrain::RobotType;
  const config::TerrainConfig defaults = fromYaml("{}", config::loadTerrainConfig);
  EXPECT_EQ(doublesOf(PursuitConfig::__getDefault__()),
            config::namedPursuitGains(defaults, RobotType::ThreeAxisRolling));
  EXPECT_EQ(PursuitConfig::__getDefault__().law,
            sr::terrain::toString(sr::PurePursuitControllerParameters{}.law));
  const PursuitConfig loaded = sr::reconfigureConfigOf(sr::terrain::PursuitLaw::Paper, defaults,
                                                       RobotType::RollingAndSteering);
  EXPECT_EQ(loaded.law, "paper");
  EXPECT_EQ(doublesOf(loaded), config::namedPursuitGains(defaults, RobotType::RollingAndSteering));
}

// Every gain goes through the node's translation both ways, to its own field: distinct values
// survive the round trip, and only the reconfigured type's gains change.
TEST(Reconfigure, PursuitControllerEveryGainRoundTrips) {
  using sr::terrain::RobotType;
  const config::TerrainConfig defaults = fromYaml("{}", config::loadTerrainConfig);
  PursuitConfig numbered = PursuitConfig::__getDefault__();
  dynamic_reconfigure::Config message;
  numbered.__toMessage__(message);
  double next = 1.0;
  for (auto& field : message.doubles) field.value = next++;
  ASSERT_TRUE(numbered.__fromMessage__(message));
  const config::TerrainConfig tuned =
      sr::withReconfiguredGains(numbered, defaults, RobotType::TwoAxisRolling);
  EXPECT_EQ(config::namedPursuitGains(tuned, RobotType::TwoAxisRolling), doublesOf(numbered));
  EXPECT_EQ(config::namedPursuitGains(tuned, RobotType::ThreeAxisRolling),
            config::namedPursuitGains(defaults, RobotType::ThreeAxisRolling));
  EXPECT_EQ(doublesOf(sr::reconfigureConfigOf(sr::terrain::PursuitLaw::Smooth, tuned,
                                              RobotType::TwoAxisRolling)),
            doublesOf(numbered));
  config::TerrainConfig renamed = defaults;
  EXPECT_INVALID_ARGUMENT(
      config::setNamedPursuitGain(renamed, RobotType::ThreeAxisRolling, "k_thta", 1.0), "k_thta");
}

// The .cfg's ranges lie inside what the laws accept at start-up (so a slider never offers a value
// the node must refuse), and what they refuse, a reconfiguration is refused for too, naming it.
TEST(Reconfigure, PursuitControllerRangesPassTheStartUpChecks) {
  using sr::terrain::PursuitLaw;
  using sr::terrain::RobotType;
  const config::TerrainConfig defaults = fromYaml("{}", config::loadTerrainConfig);
  const auto minima = doublesOf(PursuitConfig::__getMin__());
  const auto maxima = doublesOf(PursuitConfig::__getMax__());
  ASSERT_EQ(minima.size(), maxima.size());
  for (std::size_t i = 0; i < minima.size(); ++i) {
    for (double bound : {minima[i].second, maxima[i].second}) {
      config::TerrainConfig tuned = defaults;
      config::setNamedPursuitGain(tuned, RobotType::ThreeAxisRolling, minima[i].first, bound);
      for (PursuitLaw law : {PursuitLaw::Paper, PursuitLaw::Smooth})
        EXPECT_NO_THROW(config::makePursuitController(law, RobotType::ThreeAxisRolling, tuned, 0.2))
            << minima[i].first << " = " << bound;
    }
  }
  config::TerrainConfig bad = defaults;
  config::setNamedPursuitGain(bad, RobotType::ThreeAxisRolling, "k_theta", std::nan(""));
  EXPECT_INVALID_ARGUMENT(
      config::makePursuitController(PursuitLaw::Paper, RobotType::ThreeAxisRolling, bad, 0.2),
      "k_theta", "nan");
  bad = defaults;
  config::setNamedPursuitGain(bad, RobotType::RollingAndSteering, "max_tilt", 1.2);  // > pi/3
  EXPECT_INVALID_ARGUMENT(
      config::makePursuitController(PursuitLaw::Smooth, RobotType::RollingAndSteering, bad, 0.2),
      "max_tilt", "tilt limit");
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
