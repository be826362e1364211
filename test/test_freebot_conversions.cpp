// The FreeBOT stack's messages <-> core types (src/ros/freebot_conversions.cpp), without a master.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

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
      state, sr::freebot::LinkPose{}, "world", ros::Time(2.0));
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

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
