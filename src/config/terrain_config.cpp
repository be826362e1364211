#include "spherical_robots/config/terrain_config.hpp"

#include <filesystem>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "spherical_robots/config/height_map_loader.hpp"
#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/terrain/height_map_surface.hpp"

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

template <typename Gains>
using GainFields = std::initializer_list<std::pair<const char*, double Gains::*>>;

// Each gain by its name in config/terrain.yaml and cfg/PurePursuitController.cfg. k_e, common to
// every type, is terrain/gains/k_e, not terrain/gains/<type>/k_e.
const std::string kCommonPaperGain = "k_e";
constexpr GainFields<terrain::PursuitGains> kPaperGainFields = {
    {"k_theta", &terrain::PursuitGains::k_theta},   {"k_phi1", &terrain::PursuitGains::k_phi1},
    {"k_phi2", &terrain::PursuitGains::k_phi2},     {"k_psi", &terrain::PursuitGains::k_psi},
    {"k_theta1", &terrain::PursuitGains::k_theta1}, {"k_theta2", &terrain::PursuitGains::k_theta2},
    {"k_alpha", &terrain::PursuitGains::k_alpha},   {"k_phi", &terrain::PursuitGains::k_phi}};
using Smooth = terrain::SmoothPursuitGains;
constexpr GainFields<Smooth> kSmoothGainFields = {
    {"window", &Smooth::window},         {"lead", &Smooth::lead},
    {"approach_speed", &Smooth::approach_speed}, {"along_gain", &Smooth::along_gain},
    {"cross_gain", &Smooth::cross_gain}, {"heading_gain", &Smooth::heading_gain},
    {"tilt_gain", &Smooth::tilt_gain},   {"max_tilt_rate", &Smooth::max_tilt_rate},
    {"max_tilt", &Smooth::max_tilt},     {"min_speed", &Smooth::min_speed}};

/// Each named gain read from prefix + name with read(source, key, fallback); absent keys keep
/// the value gains already holds.
template <typename Gains, typename Read>
void readGains(const ParameterSource& source, const std::string& prefix, Gains& gains,
               GainFields<Gains> fields, Read read) {
  for (const auto& [name, member] : fields) {
    gains.*member = read(source, prefix + name, gains.*member);
  }
}

/// The member of gains called name, null if none is.
template <typename Gains>
double* gainNamed(Gains& gains, GainFields<Gains> fields, const std::string& name) {
  for (const auto& [field, member] : fields)
    if (name == field) return &(gains.*member);
  return nullptr;
}

terrain::PursuitGains loadGains(const ParameterSource& source, terrain::RobotType type,
                                double k_e) {
  terrain::PursuitGains gains = terrain::defaultGains(type);
  gains.k_e = k_e;
  readGains(source, kRoot + "gains/" + terrain::toString(type) + "/", gains, kPaperGainFields,
            nonNegative);
  return gains;
}

// The smooth law's gains, checked with the key in the message; the ranges are the core's.
terrain::SmoothPursuitGains loadSmoothGains(const ParameterSource& source, terrain::RobotType type) {
  const std::string prefix = kRoot + "smooth_gains/" + terrain::toString(type) + "/";
  terrain::SmoothPursuitGains gains = terrain::defaultSmoothGains(type);
  readGains(source, prefix, gains, kSmoothGainFields, finiteNumber);
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
  surface.height_map = source.text(kRoot + "surface/height_map").value_or(surface.height_map);
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

std::vector<std::pair<std::string, double>> namedPursuitGains(const TerrainConfig& config,
                                                              terrain::RobotType type) {
  const terrain::PursuitGains& paper = config.gains.at(type);
  const terrain::SmoothPursuitGains& smooth = config.smooth_gains.at(type);
  std::vector<std::pair<std::string, double>> named{{kCommonPaperGain, paper.k_e}};
  for (const auto& [name, member] : kPaperGainFields) named.emplace_back(name, paper.*member);
  for (const auto& [name, member] : kSmoothGainFields) named.emplace_back(name, smooth.*member);
  return named;
}

void setNamedPursuitGain(TerrainConfig& config, terrain::RobotType type, const std::string& name,
                         double value) {
  terrain::PursuitGains& paper = config.gains.at(type);
  double* gain = name == kCommonPaperGain ? &paper.k_e : gainNamed(paper, kPaperGainFields, name);
  if (gain == nullptr) gain = gainNamed(config.smooth_gains.at(type), kSmoothGainFields, name);
  if (gain == nullptr) throw std::invalid_argument("no pursuit gain is called '" + name + "'");
  *gain = value;
}

std::unique_ptr<terrain::Surface> makeSurface(const SurfaceSpec& spec,
                                              const SurfaceLoading& loading) {
  if (spec.type == "cosine") {
    return std::make_unique<terrain::CosineSurface>(spec.amplitude, spec.frequency);
  }
  if (spec.type == "plane") return std::make_unique<terrain::PlaneSurface>(0.0, 0.0, spec.offset);
  if (spec.type == "tilted_plane") {
    return std::make_unique<terrain::PlaneSurface>(spec.slope_x, spec.slope_y, spec.offset);
  }
  if (spec.type == "height_map") {
    if (spec.height_map.empty())
      throw std::invalid_argument("surface type height_map needs the map's YAML file (height_map)");
    std::filesystem::path path(spec.height_map);
    if (path.is_relative()) {
      path = std::filesystem::path(loading.base_directory.empty() ? packageShareDirectory()
                                                                  : loading.base_directory) /
             path;
    }
    LoadedHeightMap map = loadHeightMap(path.string());
    if (loading.warn) {
      for (const std::string& warning : map.warnings) loading.warn(warning);
    }
    return std::make_unique<terrain::HeightMapSurface>(std::move(map.grid));
  }
  throw std::invalid_argument("unknown surface type '" + spec.type +
                              "' (expected cosine, plane, tilted_plane or height_map)");
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
