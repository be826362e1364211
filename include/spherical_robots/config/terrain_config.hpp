#pragma once
// The terrain scenario's parameters (config/terrain.yaml): surface, paths, the gains of both
// tracking laws, RS tilt limit.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/terrain/pure_pursuit.hpp"
#include "spherical_robots/terrain/pursuit_law.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/terrain/smooth_pursuit.hpp"
#include "spherical_robots/terrain/surface.hpp"

namespace spherical_robots::config {

struct SurfaceSpec {
  std::string type = "cosine";  ///< "cosine" (eq 59) | "plane" | "tilted_plane" | "height_map"
  double amplitude = 0.2;       ///< cosine a [m]
  double frequency = 2.0;       ///< cosine w [rad/m]
  double slope_x = 0.0;         ///< plane g_x [-]
  double slope_y = 0.0;         ///< plane g_y [-]
  double offset = 0.0;          ///< plane z0 [m]
  /// height_map: the map's YAML (config::loadHeightMap); relative to the package's share
  /// directory unless absolute.
  std::string height_map;
};

/// How makeSurface finds a height map and tells what it had to do to it.
struct SurfaceLoading {
  /// A relative SurfaceSpec::height_map is relative to this; empty: packageShareDirectory().
  std::string base_directory;
  /// Receives each warning about the map's data (an 8-bit image and its smoothing); may be empty.
  std::function<void(const std::string&)> warn;
};

struct TerrainConfig {
  SurfaceSpec surface;
  double circle_radius = 2.0;         ///< [m]
  double circle_angular_rate = 0.05;  ///< [rad/s]
  double diamond_half_diagonal = 2.0; ///< [m]
  double diamond_speed = 0.1;         ///< [m/s]
  double tilt_limit = 1.0471975511965976;  ///< RS |phi| limit [rad], pi/3
  std::map<terrain::RobotType, terrain::PursuitGains> gains;  ///< the paper's law (eqs 55-58)
  std::map<terrain::RobotType, terrain::SmoothPursuitGains> smooth_gains;  ///< the smooth law
};

/// Reads keys under "terrain/" (see config/terrain.yaml); absent keys keep their defaults.
/// @throw std::invalid_argument naming the key, its value and the source on a bad value.
TerrainConfig loadTerrainConfig(const ParameterSource& source);

/// The law's controller for a robot of radius [m] with this scenario's gains and tilt limit.
/// @throw std::invalid_argument on bad gains or radius.
std::unique_ptr<terrain::PursuitController> makePursuitController(terrain::PursuitLaw law,
                                                                  terrain::RobotType type,
                                                                  const TerrainConfig& config,
                                                                  double radius);

/// The gains of both laws for a robot type, by the names config/terrain.yaml and
/// cfg/PurePursuitController.cfg give them: k_e (terrain/gains/k_e), then the paper law's
/// (terrain/gains/<type>/...), then the smooth law's (terrain/smooth_gains/<type>/...).
std::vector<std::pair<std::string, double>> namedPursuitGains(const TerrainConfig& config,
                                                              terrain::RobotType type);

/// Sets the gain called name (as namedPursuitGains names it) of a robot type; nothing checks the
/// value, the law's constructor does (makePursuitController).
/// @throw std::invalid_argument if no gain has that name.
void setNamedPursuitGain(TerrainConfig& config, terrain::RobotType type, const std::string& name,
                         double value);

/// @throw std::invalid_argument on an unknown type or bad numbers, or naming the height map's
/// file and what is wrong with it.
std::unique_ptr<terrain::Surface> makeSurface(const SurfaceSpec& spec,
                                              const SurfaceLoading& loading = {});

/// name: "circle" | "diamond". @throw std::invalid_argument on an unknown name.
std::unique_ptr<terrain::ReferencePath> makePath(const std::string& name, const TerrainConfig& config);

}  // namespace spherical_robots::config
