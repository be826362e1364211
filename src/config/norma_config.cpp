#include "spherical_robots/config/norma_config.hpp"

#include <initializer_list>
#include <stdexcept>
#include <utility>

namespace spherical_robots::config {
namespace {

void readPid(const ParameterSource& source, const std::string& key, norma::PidGains& pid) {
  pid.kp = finiteNumber(source, key + "/kp", pid.kp);
  pid.ki = finiteNumber(source, key + "/ki", pid.ki);
  pid.kd = finiteNumber(source, key + "/kd", pid.kd);
}

norma::ControllerGains readGains(const ParameterSource& source, const std::string& key,
                                 norma::ControllerGains g) {
  g.kinematic.k1 = finiteNumber(source, key + "kinematic/k1", g.kinematic.k1);
  g.kinematic.k2 = finiteNumber(source, key + "kinematic/k2", g.kinematic.k2);
  g.kinematic.k3 = finiteNumber(source, key + "kinematic/k3", g.kinematic.k3);
  readPid(source, key + "rate", g.rate);
  readPid(source, key + "pendulum", g.pendulum);
  readPid(source, key + "slider", g.slider);
  readPid(source, key + "tracking_slider", g.tracking_slider);
  using G = norma::ControllerGains;
  const std::initializer_list<std::pair<const char*, double G::*>> tracking = {
      {"along_gain", &G::along_gain},   {"cross_gain", &G::cross_gain},
      {"heading_gain", &G::heading_gain}, {"tilt_gain", &G::tilt_gain},
      {"tilt_damping", &G::tilt_damping}, {"max_slider", &G::max_slider}};
  for (const auto& [name, member] : tracking)
    g.*member = finiteNumber(source, key + name, g.*member);
  try {
    norma::validate(g);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source.origin() + ": parameters '" + key + "...': " + e.what());
  }
  return g;
}

}  // namespace

NormaModelParameters normaModelParameters(const ParameterSource& source, const std::string& prefix,
                                          const NormaModelParameters& fallback) {
  NormaModelParameters p;
  p.variant = parsedText(source, prefix + "variant", norma::toString(fallback.variant),
                         norma::lagrangianVariantFromString);
  p.initial_psi = finiteNumber(source, prefix + "initial_psi", fallback.initial_psi);
  return p;
}

NormaControlParameters normaControlParameters(const ParameterSource& source,
                                              const std::string& prefix,
                                              const NormaControlParameters& fallback) {
  NormaControlParameters p;
  p.controller = parsedText(source, prefix + "controller", norma::toString(fallback.controller),
                            norma::controllerKindFromString);
  p.gains = readGains(source, prefix + "gains/", fallback.gains);
  p.limits.max_torque = positiveNumber(source, prefix + "max_torque", fallback.limits.max_torque);
  p.limits.max_force = positiveNumber(source, prefix + "max_force", fallback.limits.max_force);
  return p;
}

}  // namespace spherical_robots::config
