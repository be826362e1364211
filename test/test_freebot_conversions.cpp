// The FreeBOT stack's messages <-> core types (src/ros/freebot_conversions.cpp), without a master.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <limits>
#include <stdexcept>
#include <string>

#include "spherical_robots/ros/freebot_conversions.hpp"

namespace sr = spherical_robots;

namespace {

constexpr double kMaxRate = 100.0;  // [rad/s]

}  // namespace

TEST(FreebotConversion, WheelNamesPairsAndOrder) {
  const std::vector<std::string> names = sr::conversions::freebotWheelNames(2);
  EXPECT_EQ(names, (std::vector<std::string>{"module1_wheel_right", "module1_wheel_left",
                                             "module2_wheel_right", "module2_wheel_left"}));
  // Measured state in another order, with an extra actuator: read by name.
  sensor_msgs::JointState msg;
  msg.name = {"module2_wheel_left", "other", "module1_wheel_right", "module2_wheel_right",
              "module1_wheel_left"};
  msg.velocity = {4.0, 9.0, 1.0, 3.0, 2.0};
  const auto wheels = sr::conversions::wheelSpeedsFromJointState(msg, 2, kMaxRate);
  ASSERT_EQ(wheels.size(), 2u);
  EXPECT_EQ(wheels[0].right, 1.0);
  EXPECT_EQ(wheels[0].left, 2.0);
  EXPECT_EQ(wheels[1].right, 3.0);
  EXPECT_EQ(wheels[1].left, 4.0);
  const sensor_msgs::JointState command =
      sr::conversions::jointStateFromWheelSpeeds(wheels, ros::Time(1.0));
  EXPECT_EQ(command.name, names);
  EXPECT_EQ(command.velocity, (std::vector<double>{1.0, 2.0, 3.0, 4.0}));
  msg.name.pop_back();
  EXPECT_THROW(sr::conversions::wheelSpeedsFromJointState(msg, 2, kMaxRate), std::invalid_argument);
}

TEST(FreebotConversion, ChainStateRoundTripAndRejections) {
  sr::freebot::ChainState state;
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 0).normalized()));
  state.joints = {{q, q.conjugate()}, {}};
  state.headings = {0.5, -1.0};
  spherical_robots::FreebotState msg = sr::conversions::toFreebotStateMsg(
      state, sr::freebot::LinkPose{}, "fb/link0", ros::Time(2.0));
  const sr::freebot::ChainState back = sr::conversions::chainStateFromMsg(msg);
  ASSERT_EQ(back.joints.size(), 2u);
  EXPECT_LT(back.joints[0].link.angularDistance(q), 1e-15);
  EXPECT_LT(back.joints[0].base.angularDistance(q.conjugate()), 1e-15);
  EXPECT_EQ(back.headings, state.headings);
  msg.heading.pop_back();
  EXPECT_THROW(sr::conversions::chainStateFromMsg(msg), std::invalid_argument);
  msg.heading.push_back(std::numeric_limits<double>::quiet_NaN());
  EXPECT_THROW(sr::conversions::chainStateFromMsg(msg), std::invalid_argument);
  msg.heading.back() = 0.0;
  msg.link[1].w = 2.0;  // not unit
  EXPECT_THROW(sr::conversions::chainStateFromMsg(msg), std::invalid_argument);
}

TEST(FreebotConversion, AGoalsTargetAndItsRejections) {
  geometry_msgs::PoseStamped target;
  target.pose.position.x = 0.1;
  target.pose.position.z = -0.2;
  // An all-zero orientation, an empty frame: the position only, in the base frame.
  sr::freebot::GoalPose goal = sr::conversions::goalPoseFromMsg(target, "freebot/link0", 1.0, 1e-3);
  EXPECT_EQ(goal.mode, sr::freebot::IkMode::PositionOnly);
  EXPECT_EQ(goal.position, Eigen::Vector3d(0.1, 0.0, -0.2));
  // A unit quaternion, (x, y, z, w) in the message: the full pose.
  target.header.frame_id = "freebot/link0";
  target.pose.orientation.x = 0.6;
  target.pose.orientation.w = 0.8;
  goal = sr::conversions::goalPoseFromMsg(target, "freebot/link0", 1.0, 1e-3);
  EXPECT_EQ(goal.mode, sr::freebot::IkMode::FullPose);
  EXPECT_LT(goal.orientation.angularDistance(Eigen::Quaterniond(0.8, 0.6, 0.0, 0.0)), 1e-15);
  const auto rejects = [&](const geometry_msgs::PoseStamped& bad, const std::string& field) {
    try {
      sr::conversions::goalPoseFromMsg(bad, "freebot/link0", 1.0, 1e-3);
      ADD_FAILURE() << "accepted; expected a rejection naming " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  geometry_msgs::PoseStamped bad = target;
  bad.header.frame_id = "map2";
  rejects(bad, "frame_id 'map2'");
  bad = target;
  bad.pose.position.y = std::numeric_limits<double>::quiet_NaN();
  rejects(bad, "target.pose.position");
  bad = target;
  bad.pose.position.x = 1.5;  // beyond max_distance
  rejects(bad, "target.pose.position");
  bad = target;
  bad.pose.orientation.w = 1.6;  // norm 1.7
  rejects(bad, "target.pose.orientation");
}

// The verdict's codes are the action's: the result and the feedback carry a verdict's numbers.
TEST(FreebotConversion, VerdictsBecomeResultsAndFeedback) {
  sr::freebot::GoalVerdict verdict{sr::freebot::GoalStatus::Aborted, 2e-3, 0.1, 7.5, 2, "why"};
  const spherical_robots::MoveFreebotResult result = sr::conversions::toMoveFreebotResult(verdict);
  EXPECT_EQ(result.status, spherical_robots::MoveFreebotResult::ABORTED);
  EXPECT_EQ(result.position_error, 2e-3);
  EXPECT_EQ(result.orientation_error, 0.1);
  EXPECT_EQ(result.elapsed, 7.5);
  EXPECT_EQ(result.replans, 2u);
  EXPECT_EQ(result.message, "why");
  verdict.status = sr::freebot::GoalStatus::Moving;
  EXPECT_EQ(sr::conversions::toMoveFreebotFeedback(verdict).status,
            spherical_robots::MoveFreebotFeedback::MOVING);
}

// The chain's transforms composed from the base B_0 give each sphere's pose by the manipulator's
// forward kinematics (B_n: the end effector); each trolley arrow sits on its sphere's surface.
TEST(FreebotConversion, ChainTransformsComposeToTheForwardKinematics) {
  const sr::freebot::SrcManipulator manipulator({0.05, 0.04, 0.03});
  sr::freebot::ChainState state;
  const Eigen::Quaterniond a(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized()));
  const Eigen::Quaterniond b(Eigen::AngleAxisd(-0.7, Eigen::Vector3d(0, 1, 2).normalized()));
  state.joints = {{a, b}, {b, a.conjugate()}};
  state.headings = {0.3, -1.2};
  const auto transforms = sr::conversions::freebotChainTransforms(manipulator, state, "fb/",
                                                                   ros::Time(1.0));
  ASSERT_EQ(transforms.size(), 2u);
  Eigen::Isometry3d base_from_link = Eigen::Isometry3d::Identity();
  const std::vector<sr::freebot::LinkPose> links = manipulator.forwardKinematics(state.joints);
  for (std::size_t i = 0; i < transforms.size(); ++i) {
    const auto& t = transforms[i].transform;
    EXPECT_EQ(transforms[i].header.frame_id, sr::conversions::freebotLinkFrame("fb/", i));
    EXPECT_EQ(transforms[i].child_frame_id, sr::conversions::freebotLinkFrame("fb/", i + 1));
    base_from_link = base_from_link * Eigen::Translation3d(t.translation.x, t.translation.y,
                                                             t.translation.z) *
                      Eigen::Quaterniond(t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z);
    EXPECT_LT((base_from_link.translation() - links[i].position).norm(), 1e-12) << i;
  }
  const sr::freebot::LinkPose end = manipulator.endEffector(state.joints);
  EXPECT_LT((base_from_link.translation() - end.position).norm(), 1e-12);
  EXPECT_LT(Eigen::Quaterniond(base_from_link.rotation()).angularDistance(end.orientation), 1e-12);

  const auto markers = sr::conversions::freebotChainMarkers(manipulator, state, "fb/", ros::Time(1.0));
  ASSERT_EQ(markers.markers.size(), 5u);  // three spheres, two trolleys
  for (const auto& m : markers.markers) {
    if (m.ns != "trolleys") continue;
    const std::size_t i = static_cast<std::size_t>(m.id);
    EXPECT_EQ(m.header.frame_id, sr::conversions::freebotLinkFrame("fb/", i - 1));
    const Eigen::Vector3d p(m.pose.position.x, m.pose.position.y, m.pose.position.z);
    EXPECT_NEAR(p.norm(), manipulator.radii()[i - 1], 1e-12);
  }
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
