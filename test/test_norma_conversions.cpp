// The Norma stack's messages <-> core types (src/ros/norma_conversions.cpp), without a master.
#include <gtest/gtest.h>

#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <limits>
#include <string>

#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"
#include "spherical_robots/ros/norma_conversions.hpp"

namespace sr = spherical_robots;
namespace conv = spherical_robots::conversions;

namespace {

sr::norma::NormaState someState() {
  sr::norma::NormaState state;
  state.q = sr::norma::Vector4(0.1, -0.2, 0.3, 0.04);    // θ, α, φ, δ
  state.qd = sr::norma::Vector4(1.0, -2.0, 3.0, -0.4);
  state.x = 1.5;
  state.y = -2.5;
  state.psi = 0.75;
  return state;
}

}  // namespace

TEST(NormaStateConversion, CarriesTheEffortsAndTheEnergy) {
  const sr::norma::NormaState state = someState();
  const auto msg = conv::toNormaStateMsg(state, {1.25, -3.5}, 7.0, ros::Time(2.0));
  EXPECT_EQ(msg.torque, 1.25);
  EXPECT_EQ(msg.force, -3.5);
  EXPECT_EQ(msg.energy, 7.0);
  EXPECT_EQ(msg.psi, state.psi);
}

// What the plant publishes (odom, joint_states) is what the controller measures: q, q̇, X, Y to the
// bit, ψ as the heading of the orientation (in (−π, π]), as the batch loop measures it.
TEST(NormaMeasurementConversion, OdometryAndJointStatesCarryTheState) {
  sr::norma::NormaState state = someState();
  state.psi = 7.5;  // wound up over a run
  const auto odom = conv::bodyOdometry(
      sr::bodyMotion({state.x, state.y, 0.2}, sr::yawRotation(state.psi), {0.1, 0.2, 0.0}, {0.0, 0.0, 0.3}),
      {}, "norma/odom", "norma/base_link", ros::Time(2.0));
  const sr::norma::NormaMeasurement back =
      conv::withNormaJoints(conv::normaPoseFromOdometry(odom), conv::normaJointState(state, ros::Time(2.0)));
  EXPECT_EQ(back.q, state.q);
  EXPECT_EQ(back.qd, state.qd);
  EXPECT_EQ(back.x, state.x);
  EXPECT_EQ(back.y, state.y);
  EXPECT_EQ(back.psi, sr::yawOf(sr::yawRotation(state.psi)));
  EXPECT_NEAR(back.psi, state.psi - 2.0 * M_PI, 1e-15);
}

TEST(NormaMeasurementConversion, RejectsWhatIsNoState) {
  nav_msgs::Odometry odom;
  odom.pose.pose.orientation.w = 2.0;
  EXPECT_THROW(conv::normaPoseFromOdometry(odom), std::invalid_argument);
  odom.pose.pose.orientation.w = 1.0;
  odom.pose.pose.position.x = std::nan("");
  EXPECT_THROW(conv::normaPoseFromOdometry(odom), std::invalid_argument);
  sensor_msgs::JointState joints = conv::normaJointState(someState(), ros::Time(1.0));
  joints.name[0] = "other";
  EXPECT_THROW(conv::withNormaJoints({}, joints), std::invalid_argument);
  joints = conv::normaJointState(someState(), ros::Time(1.0));
  joints.velocity[2] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(conv::withNormaJoints({}, joints), std::invalid_argument);
  joints.velocity.pop_back();
  EXPECT_THROW(conv::withNormaJoints({}, joints), std::invalid_argument);
}

// Each joint of urdf/norma.urdf gets its coordinate (docs/conventions.md, "Norma"): the tilt
// joint φ, the shell θ, the pendulum α relative to the shell, the slider δ.
TEST(NormaJointStateConversion, NamesTheUrdfsJointsWithTheirCoordinates) {
  const std::string urdf =
      sr::config::readTextFile(std::string(SPHERICAL_ROBOTS_SOURCE_DIR) + "/urdf/norma.urdf");
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf);
  ASSERT_TRUE(model);
  const sr::norma::NormaState state = someState();
  const auto msg = conv::normaJointState(state, ros::Time(1.0));
  ASSERT_EQ(msg.name.size(), 4u);
  for (const std::string& name : msg.name) EXPECT_TRUE(model->getJoint(name)) << name;
  const std::map<std::string, int> coordinate = {
      {"tilt_joint", 2}, {"shell_joint", 0}, {"pendulum_joint", 1}, {"slider_joint", 3}};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(msg.position[i], state.q(coordinate.at(msg.name[i]))) << msg.name[i];
    EXPECT_EQ(msg.velocity[i], state.qd(coordinate.at(msg.name[i]))) << msg.name[i];
  }
}

TEST(NormaCommandConversion, EffortsOfTheTwoActuatorsReadBackByName) {
  const auto msg = conv::normaEffortCommand(2.0, -30.0, ros::Time(1.0));
  EXPECT_TRUE(msg.velocity.empty());
  const auto efforts = conv::effortsByName(msg, {"slider_motor", "pendulum_motor"}, 100.0);
  EXPECT_EQ(efforts, (std::vector<double>{-30.0, 2.0}));
}

TEST(NormaTrackingErrorConversion, ErrorIsReferenceMinusPosition) {
  sr::norma::PathPoint reference;
  reference.x = 2.0;
  reference.y = 1.0;
  reference.x_dot = 0.5;
  const auto msg = conv::toNormaTrackingErrorMsg(reference, 1.5, 3.0, 2.06, 0.1, "n/odom", ros::Time(1.0));
  EXPECT_EQ(msg.header.frame_id, "n/odom");
  EXPECT_EQ(msg.error.x, 0.5);
  EXPECT_EQ(msg.error.y, -2.0);
  EXPECT_EQ(msg.desired_velocity.x, 0.5);
  EXPECT_EQ(msg.error_norm, 2.06);
}

TEST(NormaPathConversion, SamplesEq52AndCloses) {
  const double period = 200.0 * M_PI;
  const auto path = conv::lissajousPathMsg(period, 100, "n/odom", ros::Time(1.0));
  ASSERT_EQ(path.poses.size(), 101u);
  for (std::size_t k = 0; k < path.poses.size(); k += 25) {
    const sr::norma::PathPoint p = sr::norma::lissajousPath(period * k / 100);
    EXPECT_EQ(path.poses[k].pose.position.x, p.x);
    EXPECT_EQ(path.poses[k].pose.position.y, p.y);
  }
  EXPECT_NEAR(path.poses.front().pose.position.x, path.poses.back().pose.position.x, 1e-9);
  EXPECT_NEAR(path.poses.front().pose.position.y, path.poses.back().pose.position.y, 1e-9);
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
