#pragma once
// A chain of FreeBOT modules driven by their trolleys (Zong, Liang, Lam 2022, section IV): the
// chain's state integrated from the wheel speeds (eqs 64, 51, 2) and the closed-loop trolley
// position control that drives every joint to a target state (section IV-C2, eqs 53-57, 63).
// No ROS.
//
// Module i (1 … n) is link sphere B_i with its trolley inside, at the contact point with B_{i-1};
// the trolley's shell is B_i itself (r_out = l_i, r_in = l_i − shell thickness). B_0 is the fixed
// base. The trolley heading φ_i is measured in P_i (docs/conventions.md, "Trolley").

#include <cstddef>
#include <vector>

#include "spherical_robots/freebot/src_manipulator.hpp"
#include "spherical_robots/freebot/trolley_control.hpp"
#include "spherical_robots/freebot/trolley_drive.hpp"

namespace spherical_robots::freebot {

/// Every module's trolley (Table II: r_w = 0.005 m, l_w = 0.046 m, r_out − r_in = 0.002 m).
struct TrolleyGeometry {
  double wheel_radius = 0.005;     ///< r_w [m]
  double wheel_interval = 0.046;   ///< l_w [m]
  double shell_thickness = 0.002;  ///< r_out − r_in [m]
};

/// The chain's state: joint i + 1's full state and its trolley's heading φ_{i+1} [rad] in P_{i+1}.
struct ChainState {
  std::vector<SrcJointState> joints;
  std::vector<double> headings;
};

/// Limits and tolerances of the closed-loop drive.
struct DriveLimits {
  double max_forward_speed = 0.02;   ///< |u_f| [m/s]
  double max_steering_speed = 2.0;   ///< |u_s| [rad/s]
  double max_wheel_speed = 10.0;     ///< |w_r|, |w_l| [rad/s]; trolley speeds are scaled to fit
  double heading_tolerance = 0.05;   ///< [rad] above it the trolley steers in place (steer first)
  double contact_tolerance = 2e-6;   ///< [m] arc to the target contact point counted as arrived
  double steering_distance = 1e-3;   ///< [m] below this arc the heading is left alone
};

/// What drive() asks of one module.
struct ModuleDrive {
  WheelSpeeds wheels;          ///< [rad/s]
  TrolleySpeeds trolley;       ///< the speeds the wheels give [m/s, rad/s]
  double distance = 0.0;       ///< arc left to the target contact point [m]
  double heading_error = 0.0;  ///< φ^r − φ [rad] in [−π/2, π/2] (φ^r + π when reversing)
  bool arrived = false;        ///< distance <= contact_tolerance: the wheels are stopped
};

class FreebotChain {
 public:
  /// radii [m] = l_0 (the base's), l_1, …, l_n.
  /// @throw std::invalid_argument on fewer than two radii, a radius, wheel radius, interval or
  /// shell thickness not finite and > 0, a thickness >= a link radius, or a wheel interval the
  /// shell cannot hold (l_w >= 2 r_in).
  FreebotChain(const std::vector<double>& radii, const TrolleyGeometry& trolley);

  const SrcManipulator& manipulator() const { return manipulator_; }
  std::size_t moduleCount() const { return trolleys_.size(); }
  const TrolleyDrive& trolley(std::size_t module) const { return trolleys_.at(module); }

  /// All joints at the aligned start (a vertical stack), every heading 0.
  ChainState alignedState() const;

  /// The state after dt [s] >= 0 with every module's wheel speeds [rad/s] held: eq 64 gives
  /// (u_f, u_s), φ turns at u_s (eq 49) and the joint rolls at eq 51's ω(φ). The heading is taken
  /// at the middle of sub-steps that turn it by at most 0.01 rad (exact when u_s = 0 or u_f = 0).
  /// @throw std::invalid_argument on counts that do not fit, a non-finite speed or heading,
  /// a non-unit joint state, or dt not finite and >= 0.
  ChainState advance(const ChainState& state, const std::vector<WheelSpeeds>& wheels,
                     double dt) const;

  /// Section IV-C2 in closed loop, one call per control step: for each module, the arc to the
  /// target's contact point (eqs 53-55) from the current state; steer in place by eq 56 while the
  /// heading is off by more than heading_tolerance, else move by eq 63 (ṡ^r = 0, the remaining
  /// arc as s^r − s) projected on the heading as eq 57 (u_f^r cos φ_e) while eq 56 keeps steering
  /// (except within steering_distance of the target).
  /// A module whose target lies behind it (|φ^r − φ| > π/2) drives backwards (φ^r + π, −s): the
  /// shorter turn. Speeds are clamped to the limits, then scaled so that no wheel exceeds
  /// max_wheel_speed. With equal radii the contact point is the whole joint state; with unequal
  /// ones the orientation reached depends on the path (docs/conventions.md).
  /// @throw std::invalid_argument on counts that do not fit, non-unit states, a non-finite
  /// heading, or limits not finite and > 0.
  std::vector<ModuleDrive> drive(const ChainState& state, const std::vector<SrcJointState>& targets,
                                 const TrolleyGains& gains, const DriveLimits& limits) const;

  /// @throw std::invalid_argument naming the problem unless state fits this chain.
  void requireValid(const ChainState& state) const;

 private:
  SrcManipulator manipulator_;
  std::vector<TrolleyDrive> trolleys_;
};

}  // namespace spherical_robots::freebot
