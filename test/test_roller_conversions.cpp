// The roller stack's own messages (src/ros/roller_conversions.cpp), without a master.
#include <gtest/gtest.h>

#include <cmath>

#include "spherical_robots/config/roller_config.hpp"
#include "spherical_robots/ros/roller_conversions.hpp"

namespace sr = spherical_robots;
namespace conv = spherical_robots::conversions;

namespace {

Eigen::Vector3d vec(const geometry_msgs::Point& p) { return {p.x, p.y, p.z}; }

}  // namespace

TEST(RollerDriveConversion, CarriesTheDriveState) {
  sr::roller::DriveState state;
  state.omega = {1.0, -2.0, 0.5};
  state.speeds = {0.3, -0.4};
  state.slip = {0.01, -0.02};
  state.motion.speed = 0.7;
  const auto msg = conv::toRollerDriveMsg(state, ros::Time(3.0));
  EXPECT_EQ(msg.roller_speed[0], 0.3);
  EXPECT_EQ(msg.roller_speed[1], -0.4);
  EXPECT_EQ(msg.slip[1], -0.02);
  EXPECT_EQ(msg.omega.y, -2.0);
  EXPECT_EQ(msg.speed, 0.7);
}

// Each roller touches the sphere at its contact point: the cylinder's centre lies r + ρ from the
// sphere's centre (r above the floor), its axis is η_i, and the slip arrow is S_i long along X_i.
TEST(RollerMarkers, RollersTouchTheSphereAndArrowsMeasureTheSlip) {
  const double r = 0.2, rho = 0.03;
  const sr::roller::RollerActuation actuation =
      sr::config::makeRollerActuation(sr::config::RollerConfig{}, r);
  const auto& geometry = actuation.drive().geometry();
  sr::roller::DriveState state;
  state.slip = {0.05, -0.1};
  const auto markers = conv::rollerMarkers(geometry, rho, state, "heading", ros::Time(1.0));
  ASSERT_EQ(markers.markers.size(), 4u);
  const Eigen::Vector3d centre(0.0, 0.0, r);
  for (const auto& m : markers.markers) EXPECT_EQ(m.header.frame_id, "heading");
  for (int i = 0; i < 2; ++i) {
    const auto& contact = geometry.rollers()[i];
    const auto& body = markers.markers[2 * i];
    ASSERT_EQ(body.type, visualization_msgs::Marker::CYLINDER);
    EXPECT_NEAR((vec(body.pose.position) - centre).norm(), r + rho, 1e-12);
    const Eigen::Quaterniond q(body.pose.orientation.w, body.pose.orientation.x,
                               body.pose.orientation.y, body.pose.orientation.z);
    EXPECT_LT((q * Eigen::Vector3d::UnitZ() - contact.axis).norm(), 1e-12);
    EXPECT_NEAR(body.scale.x, 2 * rho, 1e-15);
    const auto& arrow = markers.markers[2 * i + 1];
    ASSERT_EQ(arrow.type, visualization_msgs::Marker::ARROW);
    ASSERT_EQ(arrow.points.size(), 2u);
    EXPECT_NEAR((vec(arrow.points[0]) - centre - contact.point).norm(), 0.0, 1e-12);
    EXPECT_NEAR((vec(arrow.points[1]) - vec(arrow.points[0])).norm(), std::abs(state.slip[i]), 1e-12);
  }
  // Distinct ids: rviz would replace one marker by another of the same namespace and id.
  EXPECT_NE(markers.markers[0].id, markers.markers[2].id);
  EXPECT_NE(markers.markers[1].id, markers.markers[3].id);
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
