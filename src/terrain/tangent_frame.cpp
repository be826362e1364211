#include "spherical_robots/terrain/tangent_frame.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

namespace spherical_robots::terrain {

namespace tangent_frame_detail {

void rejectGradient() {
  throw std::invalid_argument("tangent frame: surface gradient is not finite");
}

void rejectHeading() { throw std::invalid_argument("heading frame: psi is not finite"); }

}  // namespace tangent_frame_detail

// Eq 10.
Eigen::Vector3d surfaceNormal(const Eigen::Vector2d& gradient) {
  tangent_frame_detail::requireFiniteGradient(gradient);
  return Eigen::Vector3d(-gradient.x(), -gradient.y(), 1.0).normalized();
}

double tangentFrameSpin(const Eigen::Vector3d& normal, const Eigen::Vector3d& normal_rate) {
  return normal_rate.cross(normal).z() / (1.0 + normal.z());
}

}  // namespace spherical_robots::terrain
