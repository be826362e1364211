#pragma once
// What the terrain gtests share: the four robot types and the 16 batch cases (robot x path x
// contact model) with names gtest accepts, and a contact geometry built by hand with Eigen,
// independent of the package's tangent frame.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots::test_support {

inline const std::vector<terrain::RobotType> kAllRobotTypes = {
    terrain::RobotType::ThreeAxisRolling, terrain::RobotType::TwoAxisRolling,
    terrain::RobotType::RollingAndTurning, terrain::RobotType::RollingAndSteering};

/// "ThreeR", "TwoR", "RT", "RS": test names may not begin with a digit.
inline std::string testName(terrain::RobotType type) {
  const std::string name = terrain::toString(type);
  return name == "3R" ? "ThreeR" : name == "2R" ? "TwoR" : name;
}

/// One of the batch runs of docs/results.md.
struct BatchCase {
  terrain::RobotType type;
  const char* path;  ///< "circle" | "diamond"
  terrain::ContactModel model;
};

inline void PrintTo(const BatchCase& c, std::ostream* os) {
  *os << terrain::toString(c.type) << " on the " << c.path << ", " << terrain::toString(c.model)
      << " contact model";
}

/// The 16 cases, every type on both paths in both contact models.
inline std::vector<BatchCase> allBatchCases() {
  std::vector<BatchCase> cases;
  for (terrain::ContactModel model : {terrain::ContactModel::Paper, terrain::ContactModel::Rolling}) {
    for (const char* path : {"circle", "diamond"}) {
      for (terrain::RobotType type : kAllRobotTypes) cases.push_back({type, path, model});
    }
  }
  return cases;
}

/// "ThreeR_circle_paper", ...
inline std::string batchCaseName(const ::testing::TestParamInfo<BatchCase>& info) {
  return testName(info.param.type) + "_" + info.param.path + "_" +
         terrain::toString(info.param.model);
}

/// Eq 10 and R_L = R_T Rz(psi) with R_T the minimal rotation z -> n, via Eigen.
inline Eigen::Matrix3d headingFrameOf(const Eigen::Vector2d& gradient, double psi) {
  const Eigen::Vector3d n = Eigen::Vector3d(-gradient.x(), -gradient.y(), 1.0).normalized();
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ().cross(n);
  Eigen::Matrix3d tangent = Eigen::Matrix3d::Identity();
  if (axis.norm() > 0) {
    tangent =
        Eigen::AngleAxisd(std::atan2(axis.norm(), n.z()), axis.normalized()).toRotationMatrix();
  }
  return tangent * Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

/// The contact geometry of a sphere of radius [m] at (1, 2, 0.5) on the plane of this gradient,
/// heading psi [rad].
inline terrain::ContactGeometry geometryOn(const Eigen::Vector2d& gradient, double psi,
                                           double radius) {
  terrain::ContactGeometry geometry;
  geometry.contact_point = Eigen::Vector3d(1.0, 2.0, 0.5);
  geometry.heading_frame = headingFrameOf(gradient, psi);
  geometry.centre = geometry.contact_point + radius * geometry.heading_frame.col(2);
  geometry.gradient = gradient;
  geometry.hessian = Eigen::Matrix2d::Zero();
  return geometry;
}

}  // namespace spherical_robots::test_support
