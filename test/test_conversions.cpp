// The standard messages <-> core types (src/ros/conversions.cpp), without a master.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/ros/conversions.hpp"

namespace conv = spherical_robots::conversions;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

geometry_msgs::Twist twist(double vx, double vy, double wz) {
  geometry_msgs::Twist msg;
  msg.linear.x = vx;
  msg.linear.y = vy;
  msg.angular.z = wz;
  return msg;
}

constexpr double kMaxTwist = 10.0;  // [m/s, rad/s]

}  // namespace

TEST(TwistConversion, TakesThePlanarPartAndListsTheRest) {
  geometry_msgs::Twist msg = twist(0.2, 0.1, 0.5);
  const auto planar = conv::planarTwist(msg, kMaxTwist);
  EXPECT_EQ(planar.request.forward, 0.2);
  EXPECT_EQ(planar.request.leftward, 0.1);
  EXPECT_EQ(planar.request.yaw_rate, 0.5);
  EXPECT_TRUE(planar.ignored.empty());
  msg.linear.z = 1.0;
  msg.angular.x = 1.0;
  EXPECT_EQ(conv::planarTwist(msg, kMaxTwist).ignored, (std::vector<std::string>{"linear.z", "angular.x"}));
  EXPECT_THROW(conv::planarTwist(twist(kNaN, 0, 0), kMaxTwist), std::invalid_argument);
  EXPECT_INVALID_ARGUMENT(conv::planarTwist(twist(1e300, 0, 0), kMaxTwist), "linear.x", "10");
  EXPECT_INVALID_ARGUMENT(conv::planarTwist(twist(0, 0, -11.0), kMaxTwist), "angular.z");
}

// Every field as given: the orientation's doubles (a reader recomputes from them what the core
// computed), the twist, and the covariance diagonals in a row-major 6 x 6 with zeros elsewhere.
TEST(OdometryConversion, BodyOdometryCopiesEveryField) {
  const Eigen::Quaterniond orientation(0.6, 0.0, 0.0, 0.8 + 1e-12);  // not quite unit
  spherical_robots::config::OdometryParameters odometry;
  odometry.pose_covariance_diagonal = {1, 2, 3, 4, 5, 6};
  odometry.twist_covariance_diagonal = {7, 8, 9, 10, 11, 12};
  const auto msg = conv::bodyOdometry({{1, 2, 3}, orientation, {0.5, -0.25, 0.125}, {0, 0, 2}}, odometry,
                                      "a/odom", "a/base_link", ros::Time(3.0));
  EXPECT_EQ(msg.header.stamp, ros::Time(3.0));
  EXPECT_EQ(msg.header.frame_id, "a/odom");
  EXPECT_EQ(msg.child_frame_id, "a/base_link");
  EXPECT_EQ(msg.pose.pose.orientation.w, 0.6);
  EXPECT_EQ(msg.pose.pose.orientation.z, 0.8 + 1e-12);
  EXPECT_EQ(msg.twist.twist.linear.x, 0.5);
  EXPECT_EQ(msg.twist.twist.linear.y, -0.25);
  EXPECT_EQ(msg.twist.twist.angular.z, 2.0);
  for (int row = 0; row < 6; ++row) {
    for (int column = 0; column < 6; ++column) {
      EXPECT_EQ(msg.pose.covariance[6 * row + column], row == column ? row + 1.0 : 0.0);
      EXPECT_EQ(msg.twist.covariance[6 * row + column], row == column ? row + 7.0 : 0.0);
    }
  }
}

TEST(ImuConversion, ReadingAndCovarianceDiagonals) {
  spherical_robots::config::OdometryParameters odometry;
  odometry.imu_orientation_covariance_diagonal = {1, 2, 3};
  odometry.imu_angular_velocity_covariance_diagonal = {4, 5, 6};
  odometry.imu_linear_acceleration_covariance_diagonal = {7, 8, 9};
  spherical_robots::ImuReading reading;
  reading.angular_velocity = {0.1, 0.2, 0.3};
  reading.linear_acceleration = {0.0, 0.5, 9.81};
  const auto msg = conv::toImu(reading, odometry, "a/base_link", ros::Time(2.0));
  EXPECT_EQ(msg.header.frame_id, "a/base_link");
  EXPECT_EQ(msg.orientation.w, 1.0);
  EXPECT_EQ(msg.angular_velocity.z, 0.3);
  EXPECT_EQ(msg.linear_acceleration.z, 9.81);
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) {
      EXPECT_EQ(msg.orientation_covariance[3 * row + column], row == column ? row + 1.0 : 0.0);
      EXPECT_EQ(msg.angular_velocity_covariance[3 * row + column], row == column ? row + 4.0 : 0.0);
      EXPECT_EQ(msg.linear_acceleration_covariance[3 * row + column], row == column ? row + 7.0 : 0.0);
    }
  }
}

TEST(JointStateConversion, FieldsAsGivenAndReadBackByName) {
  const auto msg = conv::jointState({"a", "b"}, {1.0, 2.0}, {3.0, 4.0}, {}, ros::Time(5.0));
  EXPECT_EQ(msg.header.stamp, ros::Time(5.0));
  EXPECT_EQ(msg.position, (std::vector<double>{1.0, 2.0}));
  EXPECT_TRUE(msg.effort.empty());
  EXPECT_EQ(conv::velocitiesByName(msg, {"b", "a"}, 10.0), (std::vector<double>{4.0, 3.0}));
  EXPECT_THROW(conv::velocitiesByName(msg, {"b"}, 3.5), std::invalid_argument);  // |4| > 3.5
  EXPECT_THROW(conv::effortsByName(msg, {"a"}, 10.0), std::invalid_argument);    // no efforts
}

TEST(QuaternionConversion, ToMessageAndBackIsTheSameRotation) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 3).normalized()));
  const geometry_msgs::Quaternion msg = conv::toQuaternion(q);
  // Message order (x, y, z, w) against Eigen's (w, x, y, z).
  EXPECT_DOUBLE_EQ(msg.w, q.w());
  EXPECT_DOUBLE_EQ(msg.x, q.x());
  EXPECT_LT(conv::fromQuaternion(msg, "q").angularDistance(q), 1e-15);
  geometry_msgs::Quaternion scaled = msg;
  scaled.w *= 2.0;
  EXPECT_THROW(conv::fromQuaternion(scaled, "q"), std::invalid_argument);
  scaled.w = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(conv::fromQuaternion(scaled, "q"), std::invalid_argument);
}

TEST(MarkerConversion, AddedOpaqueIdentityPoseInItsFrame) {
  const auto m = conv::marker("ns", 3, visualization_msgs::Marker::ARROW, "odom", ros::Time(2.0));
  EXPECT_EQ(m.header.frame_id, "odom");
  EXPECT_EQ(m.header.stamp, ros::Time(2.0));
  EXPECT_EQ(m.action, visualization_msgs::Marker::ADD);
  EXPECT_EQ(m.pose.orientation.w, 1.0);
  EXPECT_EQ(m.color.a, 1.0f);
  const auto p = conv::toPointStamped({1.0, 2.0, 3.0}, "world", ros::Time(4.0));
  EXPECT_EQ(p.header.frame_id, "world");
  EXPECT_EQ(p.point.z, 3.0);
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
