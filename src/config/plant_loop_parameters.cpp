#include "spherical_robots/config/plant_loop_parameters.hpp"

#include <stdexcept>

namespace spherical_robots::config {

ClockMode clockModeFromString(const std::string& name) {
  if (name == "lockstep") return ClockMode::kLockstep;
  if (name == "free") return ClockMode::kFree;
  if (name == "ros") return ClockMode::kRos;
  throw std::invalid_argument("unknown clock mode (lockstep | free | ros)");
}

namespace {

/// loop_cpu as a word (auto, none, "1") or as a number (1, as YAML and roslaunch type it).
LoopCpuSetting loopCpuSetting(const ParameterSource& source, const LoopCpuSetting& fallback) {
  bool is_number = false;
  try {
    is_number = source.number("loop_cpu").has_value();
  } catch (const std::invalid_argument&) {  // a word: parsed below
  }
  if (is_number) return {LoopCpuSetting::Kind::kFixed, wholeNumber(source, "loop_cpu", 0, 0)};
  return parsedText(source, "loop_cpu", fallback.toString(), LoopCpuSetting::fromString);
}

}  // namespace

PlantLoopParameters loadPlantLoopParameters(const ParameterSource& source,
                                            const PlantLoopParameters& defaults) {
  PlantLoopParameters p = defaults;
  p.step = positiveNumber(source, "step", p.step);
  p.publish_rate = positiveNumber(source, "publish_rate", p.publish_rate);
  p.state_timeout = positiveNumber(source, "state_timeout", p.state_timeout);
  if (p.trail_period > 0.0) p.trail_period = positiveNumber(source, "trail_period", p.trail_period);
  p.duration = finiteNumber(source, "duration", p.duration);
  p.max_clock_step = positiveNumber(source, "max_clock_step", p.max_clock_step);
  p.clock = parsedText(source, "clock", "ros", clockModeFromString);
  if (p.clock == ClockMode::kLockstep) {
    p.speedup = nonNegativeNumber(source, "speedup", 0.0);
    p.lockstep_leader = source.text("lockstep_leader").value_or("");
    if (!p.lockstep_leader.empty() && p.lockstep_leader.front() != '/')
      throw std::invalid_argument(source.origin() + ": parameter 'lockstep_leader' = '" +
                                  p.lockstep_leader +
                                  "' must be an absolute namespace (\"/sphere\")");
    p.lockstep_timeout =
        positiveNumber(source, "lockstep_timeout", p.lockstep_leader.empty() ? 2.0 : 1.0);
    p.clock_rate = nonNegativeNumber(source, "clock_rate", p.clock_rate);
    p.loop_cpu = loopCpuSetting(source, p.loop_cpu);
  } else if (p.clock == ClockMode::kFree) {
    // The pace of simulated time; 0 would stop it.
    p.speedup = positiveNumber(source, "speedup", p.speedup);
  }
  p.wait_for_subscribers = wholeNumber(source, "wait_for_subscribers", p.wait_for_subscribers, 0);
  p.start_timeout = positiveNumber(source, "start_timeout", p.start_timeout);
  p.origin_x = finiteNumber(source, "origin_x", p.origin_x);
  p.origin_y = finiteNumber(source, "origin_y", p.origin_y);
  p.origin_yaw = finiteNumber(source, "origin_yaw", p.origin_yaw);
  p.checkpoint = source.text("checkpoint").value_or(p.checkpoint);
  if (p.checkpoint != "none" && p.checkpoint != "ros_home" &&
      (p.checkpoint.empty() || p.checkpoint.front() != '/'))
    throw std::invalid_argument(source.origin() + ": parameter 'checkpoint' = '" + p.checkpoint +
                                "' must be none, ros_home or an absolute directory");
  return p;
}

}  // namespace spherical_robots::config
