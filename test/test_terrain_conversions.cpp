// The terrain and roller stacks' messages <-> core types (src/ros/terrain_conversions.cpp),
// without a master.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/ros/terrain_conversions.hpp"
#include "spherical_robots/terrain/height_map_surface.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/tangent_frame.hpp"

namespace sr = spherical_robots;
namespace conv = spherical_robots::conversions;
using sr::terrain::RobotType;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

sensor_msgs::JointState jointState(std::vector<std::string> names, std::vector<double> velocities) {
  sensor_msgs::JointState msg;
  msg.name = std::move(names);
  msg.velocity = std::move(velocities);
  return msg;
}

constexpr double kMaxRate = 100.0;    // [rad/s]
constexpr double kMaxPosition = 1e3;  // [m]

}  // namespace

TEST(JointStateConversion, ReadsRatesByNameInAnyOrder) {
  const auto rates = conv::ratesFromJointState(
      RobotType::ThreeAxisRolling, jointState({"psi", "theta", "extra", "phi"}, {3.0, 1.0, 9.0, 2.0}), kMaxRate);
  EXPECT_EQ(rates.roll_rate, 1.0);
  EXPECT_EQ(rates.lateral_rate, 2.0);
  EXPECT_EQ(rates.turn_rate, 3.0);
}

TEST(JointStateConversion, UnactuatedRatesAreZero) {
  const auto rt = conv::ratesFromJointState(RobotType::RollingAndTurning,
                                            jointState({"theta", "psi", "phi"}, {1.0, 3.0, 2.0}), kMaxRate);
  EXPECT_EQ(rt.roll_rate, 1.0);
  EXPECT_EQ(rt.lateral_rate, 0.0);
  EXPECT_EQ(rt.turn_rate, 3.0);
  const auto rs = conv::ratesFromJointState(RobotType::RollingAndSteering,
                                            jointState({"alpha", "phi", "psi"}, {1.0, 2.0, 3.0}), kMaxRate);
  EXPECT_EQ(rs.roll_rate, 1.0);
  EXPECT_EQ(rs.lateral_rate, 2.0);
  EXPECT_EQ(rs.turn_rate, 0.0);
}

TEST(JointStateConversion, RejectsMissingNamesNonFiniteValuesAndShortArrays) {
  EXPECT_THROW(conv::ratesFromJointState(RobotType::TwoAxisRolling, jointState({"theta"}, {1.0}), kMaxRate),
               std::invalid_argument);
  EXPECT_THROW(conv::ratesFromJointState(RobotType::TwoAxisRolling,
                                         jointState({"theta", "phi"}, {1.0, kNaN}), kMaxRate),
               std::invalid_argument);
  EXPECT_THROW(conv::ratesFromJointState(RobotType::TwoAxisRolling,
                                         jointState({"theta", "phi"}, {1.0}), kMaxRate),
               std::invalid_argument);
  // Finite but implausible: 1e300 overflows two operations later. The bound itself is a rate.
  EXPECT_INVALID_ARGUMENT(conv::ratesFromJointState(RobotType::TwoAxisRolling,
                                                    jointState({"theta", "phi"}, {1.0, -1e300}),
                                                    kMaxRate),
                          "phi", "100", "2R");
  EXPECT_NO_THROW(conv::ratesFromJointState(RobotType::TwoAxisRolling,
                                            jointState({"theta", "phi"}, {1.0, -kMaxRate}),
                                            kMaxRate));
  // A non-finite value of a joint the type does not have is none of its business.
  EXPECT_NO_THROW(conv::ratesFromJointState(RobotType::TwoAxisRolling,
                                            jointState({"theta", "phi", "psi"}, {1.0, 2.0, kNaN}), kMaxRate));
}

TEST(JointStateConversion, WritesTheTypesActuatorsOnly) {
  const sr::terrain::DriveRates rates{1.0, 2.0, 3.0};
  const auto msg = conv::jointStateFromRates(RobotType::RollingAndTurning, rates, ros::Time(5.0));
  EXPECT_EQ(msg.name, (std::vector<std::string>{"theta", "psi"}));
  EXPECT_EQ(msg.velocity, (std::vector<double>{1.0, 3.0}));
  EXPECT_TRUE(msg.position.empty());
  EXPECT_EQ(msg.header.stamp, ros::Time(5.0));
  for (RobotType type : {RobotType::ThreeAxisRolling, RobotType::TwoAxisRolling,
                         RobotType::RollingAndTurning, RobotType::RollingAndSteering}) {
    const auto round_trip = conv::ratesFromJointState(type, conv::jointStateFromRates(type, rates, {}), kMaxRate);
    const auto expected = sr::terrain::keepActuated(type, rates);
    EXPECT_EQ(round_trip.roll_rate, expected.roll_rate);
    EXPECT_EQ(round_trip.lateral_rate, expected.lateral_rate);
    EXPECT_EQ(round_trip.turn_rate, expected.turn_rate);
  }
}

TEST(TerrainStateConversion, GeometryRoundTrip) {
  const sr::terrain::CosineSurface surface(0.2, 2.0);
  const double x = 0.7, y = -0.4, psi = 1.1, radius = 0.2;
  sr::terrain::ContactGeometry geometry;
  geometry.gradient = surface.gradient(x, y);
  geometry.heading_frame = sr::terrain::headingFrame(geometry.gradient, psi);
  geometry.contact_point = {x, y, surface.height(x, y)};
  geometry.centre = geometry.contact_point + radius * geometry.heading_frame.col(2);
  sr::terrain::TerrainState state;
  state.x = x;
  state.y = y;
  state.psi = psi;

  const auto msg = conv::toTerrainStateMsg(RobotType::ThreeAxisRolling,
                                           sr::terrain::ContactModel::Paper, state, geometry,
                                           {1.0, 2.0, 3.0}, "sphere/odom", ros::Time(2.0));
  EXPECT_EQ(msg.robot_type, "3R");
  EXPECT_EQ(msg.contact_model, "paper");
  EXPECT_EQ(msg.header.frame_id, "sphere/odom");
  EXPECT_EQ(msg.turn_rate, 3.0);
  EXPECT_EQ(msg.centre.z, geometry.centre.z());
  EXPECT_EQ(msg.heading.y, geometry.heading_frame(1, 0));
}

// What the plant publishes is what the controller reads, double for double, so the stack's
// controller sees the state the batch run's does (terrain::SampledTerrainLoop).
TEST(OdometryConversion, BodyPoseRoundTripsExactly) {
  const sr::terrain::CosineSurface surface(0.2, 2.0);
  const sr::terrain::BodyFrame frame(surface, 0.2);
  const sr::terrain::BodyPose pose =
      frame.pose(sr::terrain::contactGeometry(surface, 0.2, {0.7, -0.4, 2.9, 0.0}));
  const auto msg = conv::bodyOdometry({pose.centre, pose.orientation, {}, {}}, {}, "sphere/odom",
                                      "sphere/base_link", ros::Time(2.0));
  const sr::terrain::BodyPose back = conv::bodyPoseFromOdometry(msg, kMaxPosition);
  EXPECT_EQ(back.centre, pose.centre);
  EXPECT_EQ(back.orientation.coeffs(), pose.orientation.coeffs());
}

TEST(OdometryConversion, RejectsAPoseThatIsNotOne) {
  nav_msgs::Odometry msg;
  msg.pose.pose.orientation.w = 1.0;
  EXPECT_NO_THROW(conv::bodyPoseFromOdometry(msg, kMaxPosition));
  auto bad = msg;
  bad.pose.pose.position.y = kNaN;
  EXPECT_INVALID_ARGUMENT(conv::bodyPoseFromOdometry(bad, kMaxPosition), "pose.position.y");
  bad = msg;
  bad.pose.pose.position.x = 1e300;
  EXPECT_INVALID_ARGUMENT(conv::bodyPoseFromOdometry(bad, kMaxPosition), "pose.position.x", "1000");
  bad = msg;
  bad.pose.pose.orientation.w = 2.0;
  EXPECT_INVALID_ARGUMENT(conv::bodyPoseFromOdometry(bad, kMaxPosition), "pose.orientation", "norm");
  bad = msg;
  bad.pose.pose.orientation.z = kNaN;
  EXPECT_INVALID_ARGUMENT(conv::bodyPoseFromOdometry(bad, kMaxPosition), "pose.orientation");
}

TEST(TiltConversion, RoundTripsAndRejectsWhatIsNoTilt) {
  const auto msg = conv::tiltJointState(-0.4, 0.25, ros::Time(2.0));
  EXPECT_EQ(msg.name, std::vector<std::string>{conv::kTiltJoint});
  EXPECT_EQ(msg.velocity, std::vector<double>{0.25});
  EXPECT_EQ(conv::tiltFromJointState(msg), -0.4);
  auto bad = msg;
  bad.name = {"theta"};
  EXPECT_INVALID_ARGUMENT(conv::tiltFromJointState(bad), "lacks joint 'tilt'");
  bad = msg;
  bad.position.clear();
  EXPECT_INVALID_ARGUMENT(conv::tiltFromJointState(bad), "no position");
  bad = msg;
  bad.position = {2.0};
  EXPECT_INVALID_ARGUMENT(conv::tiltFromJointState(bad), "tilt");
  bad.position = {kNaN};
  EXPECT_THROW(conv::tiltFromJointState(bad), std::invalid_argument);
}

nav_msgs::Path pathMessage(const std::string& frame) {
  nav_msgs::Path msg;
  msg.header.frame_id = frame;
  for (int i = 0; i < 3; ++i) {
    geometry_msgs::PoseStamped pose;
    pose.header.stamp.fromSec(10.0 + i);
    pose.pose.position.x = i;
    pose.pose.position.y = 2.0 * i;
    pose.pose.position.z = 5.0;
    pose.pose.orientation.w = 1.0;
    msg.poses.push_back(pose);
  }
  return msg;
}

TEST(PathConversion, PosesBecomeStampedPointsInTheFixedFrame) {
  // The path's frame a quarter turn about z and 1 m along x from the fixed frame: (x, y) ->
  // (1 - y, x), worked by hand.
  geometry_msgs::Transform transform;
  transform.translation.x = 1.0;
  transform.rotation.z = transform.rotation.w = std::sqrt(0.5);
  const Eigen::Isometry3d to_fixed = conv::fromTransform(transform, "test");
  const std::vector<sr::terrain::StampedPoint> points =
      conv::stampedPointsFromPath(pathMessage("map_offset"), to_fixed, kMaxPosition);
  ASSERT_EQ(points.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(points[i].stamp, (10 + i) * 1000000000LL);
    EXPECT_NEAR(points[i].position.x(), 1.0 - 2.0 * i, 1e-14);
    EXPECT_NEAR(points[i].position.y(), i, 1e-14);
  }
}

TEST(PathConversion, RejectsAPoseInAnotherFrameAndBadPositions) {
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  nav_msgs::Path other_frame = pathMessage("sphere/odom");
  other_frame.poses[1].header.frame_id = "odom";
  EXPECT_INVALID_ARGUMENT(conv::stampedPointsFromPath(other_frame, identity, kMaxPosition),
                          "poses[1]", "'odom'", "'sphere/odom'");
  nav_msgs::Path not_finite = pathMessage("sphere/odom");
  not_finite.poses[2].pose.position.x = kNaN;
  EXPECT_INVALID_ARGUMENT(conv::stampedPointsFromPath(not_finite, identity, kMaxPosition),
                          "poses[2].pose.position.x", "nan");
  nav_msgs::Path far = pathMessage("sphere/odom");
  far.poses[0].pose.position.y = 1e300;
  EXPECT_INVALID_ARGUMENT(conv::stampedPointsFromPath(far, identity, kMaxPosition),
                          "poses[0].pose.position.y", "1000");
  geometry_msgs::Transform bad;
  bad.rotation.w = 2.0;
  EXPECT_INVALID_ARGUMENT(conv::fromTransform(bad, "transform from 'x'"), "transform from 'x'.rotation",
                          "norm");
}

TEST(Visualisation, SampledPathClosesOnTheSurface) {
  const sr::terrain::CosineSurface surface(0.2, 2.0);
  const sr::terrain::CirclePath circle(2.0, 0.05);
  const auto path = conv::sampledPath(circle, surface, 100, "sphere/odom", ros::Time(1.0));
  ASSERT_EQ(path.poses.size(), 100u);
  for (const auto& pose : path.poses) {
    const auto& p = pose.pose.position;
    EXPECT_NEAR(std::hypot(p.x, p.y), 2.0, 1e-12);
    EXPECT_NEAR(p.z, surface.height(p.x, p.y), 1e-12);
  }
  EXPECT_NEAR(path.poses.front().pose.position.x, path.poses.back().pose.position.x, 1e-9);
  EXPECT_NEAR(path.poses.front().pose.position.y, path.poses.back().pose.position.y, 1e-9);
  EXPECT_THROW(conv::sampledPath(circle, surface, 1, "sphere/odom", {}), std::invalid_argument);
}

TEST(Visualisation, SurfaceMeshCoversTheSquare) {
  const sr::terrain::CosineSurface surface(0.2, 2.0);
  const Eigen::AlignedBox2d square(Eigen::Vector2d(-3.0, -3.0), Eigen::Vector2d(3.0, 3.0));
  const auto mesh = conv::surfaceMesh(surface, square, 0.1, "sphere/odom", ros::Time(1.0));
  EXPECT_EQ(mesh.type, visualization_msgs::Marker::TRIANGLE_LIST);
  ASSERT_EQ(mesh.points.size(), 60u * 60u * 6u);
  EXPECT_EQ(mesh.colors.size(), mesh.points.size());
  for (const auto& p : mesh.points) {
    EXPECT_LE(std::abs(p.x), 3.0 + 1e-12);
    EXPECT_LE(std::abs(p.y), 3.0 + 1e-12);
    EXPECT_NEAR(p.z, surface.height(p.x, p.y), 1e-12);
  }
  EXPECT_THROW(conv::surfaceMesh(surface, square, 0.0, "sphere/odom", {}), std::invalid_argument);
  EXPECT_THROW(conv::surfaceMesh(surface, square, 1e-4, "sphere/odom", {}), std::invalid_argument);
  EXPECT_THROW(conv::surfaceMesh(surface, Eigen::AlignedBox2d(), 0.1, "sphere/odom", {}),
               std::invalid_argument);
}

TEST(Visualisation, SurfaceMeshOfAHeightMapSpansItsExtent) {
  // A 1.2 m x 0.8 m map: the mesh reaches every edge and never leaves the map, whose surface
  // refuses any point off it.
  sr::terrain::HeightGrid grid;
  grid.spacing = 0.1;
  grid.first_sample = {0.5, -0.4};
  grid.source = "test grid";
  grid.heights = Eigen::MatrixXd::Random(13, 9) * 0.01;
  const sr::terrain::HeightMapSurface map(grid);
  const auto mesh = conv::surfaceMesh(map, *map.domain(), 0.25, "sphere/odom", ros::Time(1.0));
  ASSERT_EQ(mesh.points.size(), 5u * 4u * 6u);  // ceil(1.2 / 0.25) x ceil(0.8 / 0.25) cells
  double x_min = 1e9, x_max = -1e9, y_min = 1e9, y_max = -1e9;
  for (const auto& p : mesh.points) {
    x_min = std::min(x_min, p.x), x_max = std::max(x_max, p.x);
    y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
    EXPECT_NEAR(p.z, map.height(p.x, p.y), 1e-12);
  }
  EXPECT_NEAR(x_min, 0.5, 1e-12);
  EXPECT_NEAR(x_max, 1.7, 1e-12);
  EXPECT_NEAR(y_min, -0.4, 1e-12);
  EXPECT_NEAR(y_max, 0.4, 1e-12);
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
