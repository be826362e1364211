#include "spherical_robots/config/roller_config.hpp"

#include <cmath>

namespace spherical_robots::config {
namespace {

const std::string kRoot = "roller/";

double radians(double degrees) { return degrees * M_PI / 180.0; }

roller::SphericalDirection loadDirection(const ParameterSource& source, const std::string& key,
                                         const roller::SphericalDirection& fallback) {
  return {finiteNumber(source, kRoot + key + "/azimuth_deg", fallback.azimuth),
          finiteNumber(source, kRoot + key + "/elevation_deg", fallback.elevation)};
}

}  // namespace

RollerConfig loadRollerConfig(const ParameterSource& source) {
  RollerConfig config;
  config.roller_radius = finiteNumber(source, kRoot + "roller_radius", config.roller_radius);
  config.contact1 = loadDirection(source, "contact1", config.contact1);
  config.contact2 = loadDirection(source, "contact2", config.contact2);
  config.alpha1 = finiteNumber(source, kRoot + "alpha1_deg", config.alpha1);
  config.alpha2 = finiteNumber(source, kRoot + "alpha2_deg", config.alpha2);
  return config;
}

roller::RollerActuation makeRollerActuation(const RollerConfig& config, double sphere_radius) {
  const auto toRadians = [](const roller::SphericalDirection& d) {
    return roller::SphericalDirection{radians(d.azimuth), radians(d.elevation)};
  };
  const roller::RollerGeometry geometry(sphere_radius, toRadians(config.contact1),
                                        toRadians(config.contact2), radians(config.alpha1),
                                        radians(config.alpha2));
  return roller::RollerActuation(roller::FrictionDrive(geometry), config.roller_radius);
}

}  // namespace spherical_robots::config
