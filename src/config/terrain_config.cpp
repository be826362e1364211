#include "spherical_robots/config/terrain_config.hpp"

#include <sstream>
#include <stdexcept>

namespace spherical_robots::config {
namespace {

const std::string kRoot = "terrain/";

double nonNegative(const ParameterSource& source, const std::string& key, double fallback) {
  const double value = finiteNumber(source, key, fallback);
  if (value < 0.0) {
    std::ostringstream message;
    message << source.origin() << ": parameter '" << key << "' must be >= 0, got " << value;
    throw std::invalid_argument(message.str());
  }
  return value;
}

terrain::PursuitGains loadGains(const ParameterSource& source, terrain::RobotType type,
                                double k_e) {
  const std::string prefix = kRoot + "gains/" + terrain::toString(type) + "/";
  terrain::PursuitGains gains = terrain::defaultGains(type);
  gains.k_e = k_e;
  const auto gain = [&](const char* name, double& value) {
    value = nonNegative(source, prefix + name, value);
  };
  gain("k_theta", gains.k_theta);
  gain("k_phi1", gains.k_phi1);
  gain("k_phi2", gains.k_phi2);
  gain("k_psi", gains.k_psi);
  gain("k_theta1", gains.k_theta1);
  gain("k_theta2", gains.k_theta2);
  gain("k_alpha", gains.k_alpha);
  gain("k_phi", gains.k_phi);
  return gains;
}

// The smooth law's gains, checked with the key in the message; the ranges are the core's.
terrain::SmoothPursuitGains loadSmoothGains(const ParameterSource& source, terrain::RobotType type) {
  const std::string prefix = kRoot + "smooth_gains/" + terrain::toString(type) + "/";
  terrain::SmoothPursuitGains gains = terrain::defaultSmoothGains(type);
  const auto gain = [&](const char* name, double& value) {
    value = finiteNumber(source, prefix + name, value);
  };
  gain("window", gains.window);
  gain("lead", gains.lead);
  gain("approach_speed", gains.approach_speed);
  gain("along_gain", gains.along_gain);
  gain("cross_gain", gains.cross_gain);
  gain("heading_gain", gains.heading_gain);
  gain("tilt_gain", gains.tilt_gain);
  gain("max_tilt_rate", gains.max_tilt_rate);
  gain("max_tilt", gains.max_tilt);
  gain("min_speed", gains.min_speed);
  try {
    terrain::validate(gains);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(source.origin() + ": " + prefix.substr(0, prefix.size() - 1) +
                                ": " + error.what());
  }
  return gains;
}

}  // namespace

TerrainConfig loadTerrainConfig(const ParameterSource& source) {
  TerrainConfig config;
  SurfaceSpec& surface = config.surface;
  surface.type = source.text(kRoot + "surface/type").value_or(surface.type);
  surface.amplitude = finiteNumber(source, kRoot + "surface/amplitude", surface.amplitude);
  surface.frequency = finiteNumber(source, kRoot + "surface/frequency", surface.frequency);
  surface.slope_x = finiteNumber(source, kRoot + "surface/slope_x", surface.slope_x);
  surface.slope_y = finiteNumber(source, kRoot + "surface/slope_y", surface.slope_y);
  surface.offset = finiteNumber(source, kRoot + "surface/offset", surface.offset);
  config.circle_radius = finiteNumber(source, kRoot + "paths/circle/radius", config.circle_radius);
  config.circle_angular_rate =
      finiteNumber(source, kRoot + "paths/circle/angular_rate", config.circle_angular_rate);
  config.diamond_half_diagonal =
      finiteNumber(source, kRoot + "paths/diamond/half_diagonal", config.diamond_half_diagonal);
  config.diamond_speed = finiteNumber(source, kRoot + "paths/diamond/speed", config.diamond_speed);
  config.tilt_limit = finiteNumber(source, kRoot + "rs_tilt_limit", config.tilt_limit);

  const std::string k_e_key = kRoot + "gains/k_e";
  const double k_e = finiteNumber(source, k_e_key, terrain::PursuitGains().k_e);
  if (k_e <= 0.0) {
    std::ostringstream message;
    message << source.origin() << ": parameter '" << k_e_key << "' must be > 0 m, got " << k_e;
    throw std::invalid_argument(message.str());
  }
  for (terrain::RobotType type :
       {terrain::RobotType::ThreeAxisRolling, terrain::RobotType::TwoAxisRolling,
        terrain::RobotType::RollingAndTurning, terrain::RobotType::RollingAndSteering}) {
    config.gains[type] = loadGains(source, type, k_e);
    config.smooth_gains[type] = loadSmoothGains(source, type);
  }
  return config;
}

std::unique_ptr<terrain::PursuitController> makePursuitController(terrain::PursuitLaw law,
                                                                  terrain::RobotType type,
                                                                  const TerrainConfig& config,
                                                                  double radius) {
  if (law == terrain::PursuitLaw::Paper) {
    return std::make_unique<terrain::PurePursuitController>(type, config.gains.at(type), radius);
  }
  return std::make_unique<terrain::SmoothPursuitController>(type, config.smooth_gains.at(type),
                                                            radius, config.tilt_limit);
}

std::unique_ptr<terrain::Surface> makeSurface(const SurfaceSpec& spec) {
  if (spec.type == "cosine") {
    return std::make_unique<terrain::CosineSurface>(spec.amplitude, spec.frequency);
  }
  if (spec.type == "plane") return std::make_unique<terrain::PlaneSurface>(0.0, 0.0, spec.offset);
  if (spec.type == "tilted_plane") {
    return std::make_unique<terrain::PlaneSurface>(spec.slope_x, spec.slope_y, spec.offset);
  }
  throw std::invalid_argument("unknown surface type '" + spec.type +
                              "' (expected cosine, plane or tilted_plane)");
}

std::unique_ptr<terrain::ReferencePath> makePath(const std::string& name,
                                                 const TerrainConfig& config) {
  if (name == "circle") {
    return std::make_unique<terrain::CirclePath>(config.circle_radius, config.circle_angular_rate);
  }
  if (name == "diamond") {
    return std::make_unique<terrain::DiamondPath>(config.diamond_half_diagonal,
                                                  config.diamond_speed);
  }
  throw std::invalid_argument("unknown path '" + name + "' (expected circle or diamond)");
}

}  // namespace spherical_robots::config
