#pragma once
// The files the package ships, read from the source tree, for the gtests that check against them
// (CMakeLists.txt defines SPHERICAL_ROBOTS_SOURCE_DIR for those).

#include <string>

#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"

#ifndef SPHERICAL_ROBOTS_SOURCE_DIR
#error "SPHERICAL_ROBOTS_SOURCE_DIR must be defined (CMakeLists.txt)"
#endif

namespace spherical_robots::test_support {

/// config/terrain.yaml of the source tree.
inline const std::string kShippedTerrainYaml = SPHERICAL_ROBOTS_SOURCE_DIR "/config/terrain.yaml";

/// The terrain stack's settings as config/terrain.yaml gives them.
inline config::TerrainConfig shippedTerrainConfig() {
  return config::loadTerrainConfig(config::YamlParameterSource(kShippedTerrainYaml));
}

}  // namespace spherical_robots::test_support
