// The FreeBOT goal executive, with no ROS master, driving the chain that freebot_plant integrates
// (FreebotChain::advance, 10 ms steps, ideal wheels) in a loop: arrival, re-plan, abort and
// timeout judged against independent truth — B_n's pose from the forward kinematics of the
// measured and of the commanded joints, the contact points from the spheres' centres, the
// tolerances, and the step at which a timeout falls due in closed form.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "spherical_robots/freebot/goal_executive.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using spherical_robots::Nanoseconds;
using spherical_robots::freebot::ChainState;
using spherical_robots::freebot::ExecutiveStep;
using spherical_robots::freebot::FreebotChain;
using spherical_robots::freebot::GoalExecutive;
using spherical_robots::freebot::GoalExecutiveParameters;
using spherical_robots::freebot::GoalPose;
using spherical_robots::freebot::GoalStatus;
using spherical_robots::freebot::GoalVerdict;
using spherical_robots::freebot::IkMode;
using spherical_robots::freebot::SrcJointState;
using spherical_robots::freebot::TrolleyGeometry;
using spherical_robots::freebot::WheelSpeeds;

constexpr Nanoseconds kStep = 10'000'000;  // freebot_plant's 10 ms
constexpr Nanoseconds kStart = 3'000'000'000;
const std::vector<double> kTableII(5, 0.034);  // 4 modules on the base, Table II
// Unequal radii: the orientation reached depends on the path (docs/results.md: one re-plan).
const std::vector<double> kUnequal = {0.04, 0.034, 0.03, 0.034, 0.04};

/// Table II's target A, full pose.
GoalPose targetA() {
  GoalPose goal;
  goal.position = Eigen::Vector3d(0.0036, 0.1636, 0.0924);
  goal.orientation = Eigen::Quaterniond(0.8610, 0.4687, 0.1356, 0.1437).normalized();
  return goal;
}

/// The angle of the rotation from a to b [rad], from the quaternion's half-angle.
double rotationAngle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const Eigen::Quaterniond d = a.conjugate() * b;
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

struct PoseErrors {
  double position;
  double orientation;
};

/// B_n's errors to the goal, from the forward kinematics of these joints.
PoseErrors errorsOf(const FreebotChain& chain, const std::vector<SrcJointState>& joints,
                    const GoalPose& goal) {
  const auto links = chain.manipulator().forwardKinematics(joints);
  return {(links.back().position - goal.position).norm(),
          goal.mode == IkMode::FullPose ? rotationAngle(links.back().orientation, goal.orientation)
                                        : 0.0};
}

/// The largest arc [m] on B_{i-1} between the contact points of two chains: each contact point
/// lies on the line of the spheres' centres, at l_{i-1} from B_{i-1}'s, in B_{i-1}'s frame.
double largestContactArc(const FreebotChain& chain, const std::vector<SrcJointState>& a,
                         const std::vector<SrcJointState>& b) {
  const auto pa = chain.manipulator().forwardKinematics(a);
  const auto pb = chain.manipulator().forwardKinematics(b);
  const auto normal = [](const auto& poses, std::size_t i) {
    const Eigen::Vector3d base = i == 0 ? Eigen::Vector3d::Zero() : poses[i - 1].position;
    const Eigen::Quaterniond frame =
        i == 0 ? Eigen::Quaterniond::Identity() : poses[i - 1].orientation;
    return Eigen::Vector3d(frame.conjugate() * (poses[i].position - base).normalized());
  };
  double largest = 0.0;
  for (std::size_t i = 0; i < chain.moduleCount(); ++i) {
    const Eigen::Vector3d na = normal(pa, i), nb = normal(pb, i);
    const double angle = std::atan2(na.cross(nb).norm(), na.dot(nb));
    largest = std::max(largest, chain.manipulator().radii()[i] * angle);
  }
  return largest;
}

/// A verdict with the step it came at and the state it judged.
struct Event {
  GoalVerdict verdict;
  Nanoseconds t;
  ChainState state;
  std::vector<SrcJointState> joint_targets;
};

/// The executive and the plant in a loop, as the lock-step stack runs them: at t the plant's
/// state goes to step(), whose wheel speeds the plant then holds for 10 ms.
class Loop {
 public:
  Loop(const std::vector<double>& radii, const GoalExecutiveParameters& parameters)
      : chain_(radii, TrolleyGeometry{}), executive_(chain_, parameters),
        state_(chain_.alignedState()) {
    stepOnce();  // a first measurement to plan from
  }

  /// Accepts the goal now; its verdict.
  GoalVerdict accept(const GoalPose& goal) {
    goal_ = goal;
    accepted_ = t_;
    return executive_.accept(goal, t_);
  }

  /// Steps until a verdict ends the goal or `limit` [s] passes; the events on the way.
  std::vector<Event> runUntilDone(double limit) {
    std::vector<Event> events;
    const Nanoseconds end = t_ + static_cast<Nanoseconds>(limit * 1e9);
    while (t_ < end) {
      const ChainState judged = state_;
      const ExecutiveStep step = stepOnce();
      for (const GoalVerdict& verdict : step.verdicts)
        events.push_back({verdict, t_ - kStep, judged, step.joint_targets});
      if (!executive_.active()) break;
    }
    return events;
  }

  /// One step; also checks the wheel limit every step.
  ExecutiveStep stepOnce() {
    measured_ = state_;
    const ExecutiveStep step = executive_.step(t_, state_);
    for (const WheelSpeeds& w : step.wheels) {
      EXPECT_LE(std::abs(w.right), executive_.parameters().limits.max_wheel_speed + 1e-12);
      EXPECT_LE(std::abs(w.left), executive_.parameters().limits.max_wheel_speed + 1e-12);
    }
    last_wheels_ = step.wheels;
    state_ = chain_.advance(state_, step.wheels, 1e-9 * kStep);
    t_ += kStep;
    return step;
  }

  /// Every wheel of the last step exactly at rest.
  bool wheelsAtRest() const {
    return std::all_of(last_wheels_.begin(), last_wheels_.end(),
                       [](const WheelSpeeds& w) { return w.right == 0.0 && w.left == 0.0; });
  }

  const FreebotChain& chain() const { return chain_; }
  GoalExecutive& executive() { return executive_; }
  const ChainState& state() const { return state_; }
  /// The state the last step measured (state() is where its wheels took the chain).
  const ChainState& measured() const { return measured_; }
  Nanoseconds now() const { return t_; }
  const GoalPose& goal() const { return goal_; }
  /// [s] from the goal's acceptance to the step at t.
  double secondsSinceAccepted(Nanoseconds t) const {
    return 1e-9 * static_cast<double>(t - accepted_);
  }

 private:
  FreebotChain chain_;
  GoalExecutive executive_;
  ChainState state_;
  ChainState measured_;
  Nanoseconds t_ = kStart;
  Nanoseconds accepted_ = 0;
  GoalPose goal_;
  std::vector<WheelSpeeds> last_wheels_;
};

/// A Moving verdict: the commanded joints put B_n within IK's own tolerances of the goal, and
/// the verdict reports those errors.
void expectSolved(const FreebotChain& chain, const GoalVerdict& verdict,
                  const std::vector<SrcJointState>& commanded, const GoalPose& goal,
                  const GoalExecutiveParameters& parameters) {
  ASSERT_EQ(verdict.status, GoalStatus::Moving) << verdict.message;
  ASSERT_EQ(commanded.size(), chain.moduleCount());
  const PoseErrors truth = errorsOf(chain, commanded, goal);
  EXPECT_LE(truth.position, parameters.ik.position_tolerance);
  EXPECT_LE(truth.orientation, parameters.ik.orientation_tolerance);
  EXPECT_NEAR(verdict.position_error, truth.position, 1e-12);
  EXPECT_NEAR(verdict.orientation_error, truth.orientation, 1e-9);
}

/// A verdict on the measured state: its errors are the forward kinematics' of that state.
void expectMeasured(const Loop& loop, const Event& event) {
  const PoseErrors truth = errorsOf(loop.chain(), event.state.joints, loop.goal());
  EXPECT_NEAR(event.verdict.position_error, truth.position, 1e-12);
  EXPECT_NEAR(event.verdict.orientation_error, truth.orientation, 1e-9);
  EXPECT_NEAR(event.verdict.elapsed, loop.secondsSinceAccepted(event.t), 1e-12);
}

/// After the goal ended: the wheels at rest, the chain where it was, and no more verdicts.
void expectHolds(Loop& loop) {
  const ChainState before = loop.state();
  for (int k = 0; k < 50; ++k) EXPECT_TRUE(loop.stepOnce().verdicts.empty());
  EXPECT_TRUE(loop.wheelsAtRest());
  EXPECT_FALSE(loop.executive().active());
  for (std::size_t i = 0; i < before.joints.size(); ++i) {
    EXPECT_EQ(loop.state().joints[i].link.coeffs(), before.joints[i].link.coeffs());
    EXPECT_EQ(loop.state().joints[i].base.coeffs(), before.joints[i].base.coeffs());
  }
}

TEST(GoalExecutive, ArrivesAtTargetAWithinTheGoalTolerances) {
  const GoalExecutiveParameters parameters;
  Loop loop(kTableII, parameters);
  const GoalVerdict planned = loop.accept(targetA());
  const ExecutiveStep first = loop.stepOnce();
  expectSolved(loop.chain(), planned, first.joint_targets, loop.goal(), parameters);

  const std::vector<Event> events = loop.runUntilDone(60.0);
  ASSERT_EQ(events.size(), 1u);
  const Event& arrival = events[0];
  ASSERT_EQ(arrival.verdict.status, GoalStatus::Arrived) << arrival.verdict.message;
  expectMeasured(loop, arrival);
  EXPECT_LE(arrival.verdict.position_error, parameters.position_tolerance);
  EXPECT_LE(arrival.verdict.orientation_error, parameters.orientation_tolerance);
  // Equal radii: the contact points are the joint states, so arrival is every trolley within
  // contact_tolerance of its target's contact point.
  EXPECT_LE(largestContactArc(loop.chain(), arrival.state.joints, first.joint_targets),
            parameters.limits.contact_tolerance + 1e-12);
  EXPECT_LT(arrival.verdict.elapsed, 10.0);  // the stack: 4.8-5.1 s (docs/results.md)
  expectHolds(loop);
}

TEST(GoalExecutive, RePlansWhenUnequalRadiiReachTheContactPointsButNotThePose) {
  const GoalExecutiveParameters parameters;
  Loop loop(kUnequal, parameters);
  ASSERT_EQ(loop.accept(targetA()).status, GoalStatus::Moving);
  const ExecutiveStep first = loop.stepOnce();
  const std::vector<Event> events = loop.runUntilDone(60.0);
  ASSERT_GE(events.size(), 2u);
  for (std::size_t k = 0; k + 1 < events.size(); ++k) {
    const Event& replan = events[k];
    SCOPED_TRACE("re-plan " + std::to_string(k + 1));
    // Re-planned exactly when the contact points of the previous solution were reached (within
    // contact_tolerance) and B_n was outside the goal tolerances.
    const std::vector<SrcJointState>& previous =
        k == 0 ? first.joint_targets : events[k - 1].joint_targets;
    EXPECT_LE(largestContactArc(loop.chain(), replan.state.joints, previous),
              parameters.limits.contact_tolerance + 1e-12);
    const PoseErrors reached = errorsOf(loop.chain(), replan.state.joints, loop.goal());
    EXPECT_TRUE(reached.position > parameters.position_tolerance ||
                reached.orientation > parameters.orientation_tolerance);
    expectSolved(loop.chain(), replan.verdict, replan.joint_targets, loop.goal(), parameters);
    EXPECT_NE(replan.verdict.message.find("re-plan " + std::to_string(k + 1) + " of 3"),
              std::string::npos)
        << replan.verdict.message;
    EXPECT_EQ(replan.verdict.replans, static_cast<int>(k + 1));
  }
  const Event& arrival = events.back();
  ASSERT_EQ(arrival.verdict.status, GoalStatus::Arrived) << arrival.verdict.message;
  expectMeasured(loop, arrival);
  EXPECT_LE(arrival.verdict.position_error, parameters.position_tolerance);
  EXPECT_LE(arrival.verdict.orientation_error, parameters.orientation_tolerance);
  expectHolds(loop);
}

TEST(GoalExecutive, AbortsWhenTheRePlansAreUsedUp) {
  GoalExecutiveParameters parameters;
  parameters.max_replans = 0;
  Loop loop(kUnequal, parameters);
  loop.accept(targetA());
  const ExecutiveStep first = loop.stepOnce();
  const std::vector<Event> events = loop.runUntilDone(60.0);
  ASSERT_EQ(events.size(), 1u);
  const Event& abort = events[0];
  ASSERT_EQ(abort.verdict.status, GoalStatus::Aborted) << abort.verdict.message;
  expectMeasured(loop, abort);
  // Aborted at the contact points of the one solution, outside the goal tolerances.
  EXPECT_LE(largestContactArc(loop.chain(), abort.state.joints, first.joint_targets),
            parameters.limits.contact_tolerance + 1e-12);
  EXPECT_TRUE(abort.verdict.position_error > parameters.position_tolerance ||
              abort.verdict.orientation_error > parameters.orientation_tolerance);
  EXPECT_NE(abort.verdict.message.find("after 0 re-plans"), std::string::npos);
  expectHolds(loop);
}

TEST(GoalExecutive, TimesOutAtTheFirstStepPastTheTimeoutAndHoldsThePose) {
  GoalExecutiveParameters parameters;
  parameters.timeout = 1.0;  // target A needs about 5 s
  Loop loop(kTableII, parameters);
  loop.accept(targetA());
  const std::vector<Event> events = loop.runUntilDone(60.0);
  ASSERT_EQ(events.size(), 1u);
  const Event& timeout = events[0];
  ASSERT_EQ(timeout.verdict.status, GoalStatus::Aborted) << timeout.verdict.message;
  // Steps every 10 ms from the goal's step: 1.00 s is not past 1 s, 1.01 s is.
  EXPECT_EQ(timeout.t - kStart - kStep, 101 * kStep);
  EXPECT_DOUBLE_EQ(timeout.verdict.elapsed, 1.01);
  expectMeasured(loop, timeout);
  EXPECT_GT(timeout.verdict.position_error, parameters.position_tolerance);
  EXPECT_NE(timeout.verdict.message.find("timeout"), std::string::npos);
  expectHolds(loop);
}

TEST(GoalExecutive, AnUnreachableGoalMovesNothing) {
  const GoalExecutiveParameters parameters;
  Loop loop(kTableII, parameters);
  GoalPose far;
  far.position = Eigen::Vector3d(0.25, 0.2, 0.1);  // 0.335 m from the base's centre
  const double reach = 4 * 0.068;                   // Σ (l_{i-1} + l_i)
  const GoalVerdict verdict = loop.accept(far);
  EXPECT_EQ(verdict.status, GoalStatus::Unreachable);
  // No pose within the reach is closer than |r| − reach.
  EXPECT_GE(verdict.position_error, far.position.norm() - reach - 1e-12);
  EXPECT_NE(verdict.message.find("beyond the reach"), std::string::npos);
  EXPECT_FALSE(loop.executive().active());
  expectHolds(loop);
}

TEST(GoalExecutive, ProgressIsTheMeasuredChainsErrorsToTheGoalInForce) {
  const GoalExecutiveParameters parameters;
  Loop loop(kTableII, parameters);
  EXPECT_FALSE(loop.stepOnce().progress);  // no goal: nothing to report
  const GoalVerdict planned = loop.accept(targetA());
  for (int k = 1; k <= 300; ++k) {
    const ExecutiveStep step = loop.stepOnce();
    ASSERT_TRUE(step.progress);
    const PoseErrors truth = errorsOf(loop.chain(), loop.measured().joints, loop.goal());
    EXPECT_EQ(step.progress->status, GoalStatus::Moving);
    EXPECT_NEAR(step.progress->position_error, truth.position, 1e-12);
    EXPECT_NEAR(step.progress->orientation_error, truth.orientation, 1e-9);
    EXPECT_NEAR(step.progress->elapsed, 1e-9 * static_cast<double>((k - 1) * kStep), 1e-12);
    EXPECT_EQ(step.progress->replans, 0);
    EXPECT_EQ(step.progress->message, planned.message);
  }
  const std::vector<Event> events = loop.runUntilDone(60.0);
  ASSERT_EQ(events.back().verdict.status, GoalStatus::Arrived);
  EXPECT_FALSE(loop.stepOnce().progress);
}

TEST(GoalExecutive, ACancelStopsTheChainWhereItStandsAndANewGoalFollows) {
  const GoalExecutiveParameters parameters;
  Loop loop(kTableII, parameters);
  EXPECT_THROW(loop.executive().cancel(loop.now()), std::logic_error);
  loop.accept(targetA());
  for (int k = 0; k < 100; ++k) loop.stepOnce();
  EXPECT_THROW(loop.accept(targetA()), std::logic_error);
  const GoalVerdict stopped = loop.executive().cancel(loop.now());
  EXPECT_EQ(stopped.status, GoalStatus::Preempted);
  // Measured: the chain the last step saw, 1 s after the goal (100 steps of 10 ms), still far.
  const PoseErrors truth = errorsOf(loop.chain(), loop.measured().joints, loop.goal());
  EXPECT_NEAR(stopped.position_error, truth.position, 1e-12);
  EXPECT_NEAR(stopped.orientation_error, truth.orientation, 1e-9);
  EXPECT_GT(stopped.position_error, parameters.position_tolerance);
  EXPECT_NEAR(stopped.elapsed, 1.0, 1e-12);
  EXPECT_FALSE(loop.executive().active());
  expectHolds(loop);  // every wheel at zero from the next step on: the joints stay put

  GoalPose position_only;
  position_only.position = Eigen::Vector3d(0.05, 0.12, 0.15);
  position_only.mode = IkMode::PositionOnly;
  const GoalVerdict planned = loop.accept(position_only);
  const ExecutiveStep first = loop.stepOnce();
  expectSolved(loop.chain(), planned, first.joint_targets, position_only, parameters);
  const std::vector<Event> events = loop.runUntilDone(60.0);
  ASSERT_EQ(events.size(), 1u);
  ASSERT_EQ(events[0].verdict.status, GoalStatus::Arrived) << events[0].verdict.message;
  expectMeasured(loop, events[0]);
  EXPECT_EQ(events[0].verdict.orientation_error, 0.0);  // the position only
  EXPECT_LE(events[0].verdict.position_error, parameters.position_tolerance);
}

TEST(GoalExecutive, RefusesWhatItCannotPlanAndChangesNothing) {
  const FreebotChain chain(kTableII, TrolleyGeometry{});
  GoalExecutive executive(chain, GoalExecutiveParameters{});
  EXPECT_INVALID_ARGUMENT(executive.accept(targetA(), kStart), "no chain state");
  executive.step(kStart, chain.alignedState());
  GoalPose bad = targetA();
  bad.position.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_INVALID_ARGUMENT(executive.accept(bad, kStart + kStep), "target x");
  bad = targetA();
  bad.orientation.coeffs() *= 2.0;
  EXPECT_INVALID_ARGUMENT(executive.accept(bad, kStart + kStep), "target orientation");
  EXPECT_FALSE(executive.active());
  ASSERT_EQ(executive.accept(targetA(), kStart + kStep).status, GoalStatus::Moving);
  ChainState short_state = chain.alignedState();
  short_state.headings.pop_back();
  EXPECT_INVALID_ARGUMENT(executive.step(kStart + 2 * kStep, short_state), "heading count");
  EXPECT_EQ(executive.measurement()->headings.size(), chain.moduleCount());
  EXPECT_TRUE(executive.active());
}

TEST(GoalExecutive, BadParametersAreNamed) {
  const FreebotChain chain(kTableII, TrolleyGeometry{});
  GoalExecutiveParameters p;
  p.position_tolerance = 0.0;
  EXPECT_INVALID_ARGUMENT(GoalExecutive(chain, p), "goal position tolerance", "0");
  p = {};
  p.orientation_tolerance = std::numeric_limits<double>::infinity();
  EXPECT_INVALID_ARGUMENT(GoalExecutive(chain, p), "goal orientation tolerance", "inf");
  p = {};
  p.timeout = -1.0;
  EXPECT_INVALID_ARGUMENT(GoalExecutive(chain, p), "goal timeout", "-1");
  p = {};
  p.max_replans = -1;
  EXPECT_INVALID_ARGUMENT(GoalExecutive(chain, p), "re-plans", ">= 0", "-1");
}

TEST(GoalExecutive, EveryStatusHasItsName) {
  EXPECT_STREQ(toString(GoalStatus::Moving), "moving");
  EXPECT_STREQ(toString(GoalStatus::Arrived), "arrived");
  EXPECT_STREQ(toString(GoalStatus::Unreachable), "unreachable");
  EXPECT_STREQ(toString(GoalStatus::Rejected), "rejected");
  EXPECT_STREQ(toString(GoalStatus::Preempted), "preempted");
  EXPECT_STREQ(toString(GoalStatus::Aborted), "aborted");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
