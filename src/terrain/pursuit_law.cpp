#include "spherical_robots/terrain/pursuit_law.hpp"
#include "spherical_robots/core/validation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spherical_robots::terrain {

// Eq 53, and eq 54 signed: atan2 of e_t's components along l and h.
TrackingError trackingError(const ContactGeometry& geometry, const Eigen::Vector3d& desired,
                            bool with_zeta) {
  if (!allFinite(desired.x(), desired.y(), desired.z())) throw std::invalid_argument("tracking error: desired point not finite");
  TrackingError result;
  result.error = desired - geometry.contact_point;
  result.norm = result.error.norm();
  if (!with_zeta) return result;
  const double along_heading = result.error.dot(geometry.heading_frame.col(0));
  const double along_left = result.error.dot(geometry.heading_frame.col(1));
  // Along n the direction in the plane is round-off, not information. hypot(a, b) is never below
  // max(|a|, |b|), so the larger component alone settles the usual case without the slow hypot.
  const double round_off = 1e-12 * result.norm;
  if (std::max(std::abs(along_heading), std::abs(along_left)) > round_off ||
      std::hypot(along_heading, along_left) > round_off) {
    result.zeta = std::atan2(along_left, along_heading);
  }
  return result;
}

}  // namespace spherical_robots::terrain
