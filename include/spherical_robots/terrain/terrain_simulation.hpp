#pragma once
// Closed-loop batch run of a terrain robot: classical fixed-step RK4 (Boost.Odeint) with the
// tracking law (paper or smooth) evaluated at every stage (continuous-time feedback).

#include <Eigen/Geometry>
#include <array>
#include <limits>
#include <utility>

#include "spherical_robots/terrain/pursuit_law.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/smooth_pursuit.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots::terrain {

/// Everything observable at one instant of a closed-loop run.
struct TerrainSample {
  double t = 0.0;
  TerrainState state;
  ContactGeometry geometry;
  DesiredPoint desired;
  TrackingError error;
  DriveRates rates;  ///< realised drive rates [rad/s]
};

class TerrainSimulation {
 public:
  /// The kinematics, controller and path must outlive the simulation.
  TerrainSimulation(const TerrainKinematics& kinematics, const PursuitController& controller,
                    const ReferencePath& path, const TerrainState& initial);

  /// Advances by dt [s] > 0 with one RK4 step. @throw std::invalid_argument on a bad dt,
  /// std::runtime_error if the state stops being finite.
  void step(double dt);

  TerrainSample sample() const;
  double time() const { return t_; }
  const TerrainState& state() const { return state_; }

  /// The closed-loop vector field at (state, t): the controller's command realised by the robot.
  TerrainSample evaluate(const TerrainState& state, double t) const;

 private:
  /// p_d(t) with the velocity the controller wants (over its window), remembered for
  /// the two latest times: a step's end is the next step's start (and sample()'s time).
  const DesiredPoint& desiredAt(double t) const;
  /// One RK4 step of dt [s] with `controller`: controller_ itself, or controller_ as its final
  /// class, whose command() the RK stages then call directly and may inline.
  template <typename Controller>
  [[gnu::flatten]] void advance(const Controller& controller, double dt);

  const TerrainKinematics& kinematics_;
  const PursuitController& controller_;
  /// controller_ if it is the smooth law, nullptr otherwise.
  const SmoothPursuitController* smooth_controller_;
  const ReferencePath& path_;
  // The controller's constants, read once instead of by a virtual call at every RK stage.
  VelocityWindow velocity_window_;
  bool reads_zeta_;
  TerrainState state_;
  double t_ = 0.0;
  double t_compensation_ = 0.0;  ///< Kahan: 40,000 steps of 5 ms end at exactly 200 s
  /// The cached points and how many of the slots hold one (no NaN "empty" time: a build with
  /// -ffast-math may assume NaN away, and the run's figures must not depend on the build).
  mutable std::array<std::pair<double, DesiredPoint>, 2> desired_cache_;
  mutable std::size_t desired_cache_used_ = 0;
  mutable std::size_t desired_cache_next_ = 0;
};

/// One RK4 step [s] of the open-loop kinematics with rates held constant over the step, as a plant
/// fed by measured actuator rates integrates them. @throw std::invalid_argument on a bad dt.
TerrainState stepWithHeldRates(const TerrainKinematics& kinematics, const TerrainState& state,
                               const DriveRates& rates, double dt);

/// The shell orientation (world <- body) after turning at omega [rad/s, world frame] for dt [s]
/// (exact for constant omega: q <- exp(omega dt / 2) q).
Eigen::Quaterniond advanceOrientation(const Eigen::Quaterniond& orientation,
                                      const Eigen::Vector3d& omega, double dt);

/// A plant's whole state: the configuration and the shell's orientation (world <- shell).
struct RollingState {
  TerrainState state;
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

/// Advances by elapsed [s] > 0 with the rates held, in equal RK4 sub-steps no longer than
/// max_step [s] > 0; the shell turns by the mean of its angular velocities at each sub-step's ends
/// (second order, like the state). @throw std::invalid_argument on bad times or input,
/// std::runtime_error if the state stops being finite.
RollingState advanceWithHeldRates(const TerrainKinematics& kinematics, const RollingState& start,
                                  const DriveRates& rates, double elapsed, double max_step);

/// The tracking figures the paper reports: time of the first |e_t| below a threshold, and the
/// mean and max of |e_t| from a settling time on.
class TrackingSummary {
 public:
  /// @param threshold [m] (0.1 in the paper's sense of "converged"), @param settle_time [s] (40).
  TrackingSummary(double threshold, double settle_time);
  void add(double t, double error_norm);

  /// NaN if |e_t| never went below the threshold.
  double timeToConverge() const { return time_to_converge_; }
  /// NaN if no sample had t >= settle_time.
  double meanAfterSettling() const;
  double maxAfterSettling() const;
  double threshold() const { return threshold_; }
  double settleTime() const { return settle_time_; }

 private:
  double threshold_;
  double settle_time_;
  bool converged_ = false;  ///< a flag, not isnan(time_to_converge_): see desired_cache_
  double time_to_converge_ = std::numeric_limits<double>::quiet_NaN();
  double sum_after_ = 0.0;
  double max_after_ = 0.0;
  long count_after_ = 0;
};

}  // namespace spherical_robots::terrain
