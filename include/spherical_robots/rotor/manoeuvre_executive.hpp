#pragma once
// The rotor manoeuvre executive: what the two-rotor sphere (Svinin et al.) commands, step by step,
// to execute a plan of the geometric-phase planner and, optionally, to close the loop over whole
// manoeuvres (manoeuvre_correction.hpp). Time is a number (whole nanoseconds, as ros::Time carries
// it), the measured sphere a plain struct, the output a set-point or nothing, so the rotor_planner
// node, sphere_sim rotor-execute and the gtests reach every decision alike. No ROS.
//
// One execution: a plan's figure eight traced n times from rest to rest along CurveTiming (its
// θ̇ lowered if the rotors would exceed their limit), eq 11 set-points (planSetPointAt), with the
// feed-forward of a first-order rotor lag if one is given, sampled every command period, then one
// zero; then `settle` s at rest. With corrections left, the measured rest then decides: the
// contact off the south pole, and the last manoeuvre not already such an arc: a PoleReturnArc;
// else, off the goal by more than the tolerances: a one-step figure eight from there to the goal.
// Otherwise the execution is finished. A cancel ends it where the sphere stands: the rotors are
// commanded to rest at the next step.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/manoeuvre_correction.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"
#include "spherical_robots/rotor/plan_execution.hpp"

namespace spherical_robots::rotor {

/// What the executive is doing after a step.
enum class ManoeuvreState {
  kIdle,             ///< no manoeuvre: nothing is commanded
  kExecuting,        ///< tracing the plan's figure eights
  kReturningToPole,  ///< tracing a PoleReturnArc (a correction)
  kCorrecting,       ///< tracing a corrective figure eight
  kSettling,         ///< a manoeuvre has ended in a zero set-point: waiting for the sphere to rest
};

/// "idle", "executing", "returning to pole", "correcting", "settling".
const char* toString(ManoeuvreState state);

/// The sphere as measured (e.g. from odometry): its rest pose and where the contact sits on it.
struct RestMeasurement {
  RestPose pose;                   ///< contact point (u_a, v_a) [R] on the plane, ψ [rad]
  Eigen::Vector2d contact_angles;  ///< (u_o, v_o) [rad] on the sphere; (0, 0): the south pole
  bool fresh = true;  ///< within its input's timeout; no correction is planned from a stale one
};

/// measuredRestPose and measuredContactAngles of a sphere whose centre is at (centre_x, centre_y)
/// [m] with the attitude of Σ_o in Σ_a. @throw std::invalid_argument as those two.
RestMeasurement measureRest(double centre_x, double centre_y, double radius,
                            const Eigen::Quaterniond& attitude);

/// How far a rest is from a goal: on the plane [m] and in heading [rad].
struct Miss {
  double distance = 0.0;
  double heading = 0.0;
};

/// How an execution ended.
enum class ManoeuvreEnd {
  kExecuted,  ///< traced, with its corrections, and settled: the miss is where the sphere rests
  kRefused,   ///< it could not start (no set-points for the plan): nothing was commanded
  kCanceled,  ///< cancel(): the rotors are brought to rest where the sphere stands
};

/// "executed", "refused", "canceled".
const char* toString(ManoeuvreEnd end);

/// The verdict on one execution: a plan and the corrections after it.
struct ManoeuvreVerdict {
  ManoeuvreEnd end = ManoeuvreEnd::kExecuted;
  std::uint32_t index = 0;  ///< the plan executed
  Miss miss;                ///< of the measured sphere (the zero state if none) from the goal
  int corrections = 0;      ///< corrective manoeuvres made in this execution
  double elapsed = 0.0;     ///< [s] since the execution started; 0 if it never did
  std::string message;      ///< for a person
};

/// Where an execution in progress stands after a step.
struct ManoeuvreProgress {
  ManoeuvreState state = ManoeuvreState::kExecuting;
  /// [0, 1] of the time of the manoeuvre being traced (the plan's, or a correction's); 1 while
  /// settling.
  double fraction = 0.0;
  Miss miss;              ///< of the measured sphere (the zero state if none) from the goal
  int corrections = 0;    ///< made so far in this execution
  double elapsed = 0.0;   ///< [s] since the execution started
};

class ManoeuvreExecutive {
 public:
  struct Parameters {
    double radius = 0.1;          ///< sphere radius R [m]: the plane's tolerances and misses are in m
    double inertia_scale = 12.0;  ///< J_zz / J_r, > 0
    double curve_rate = 1.0;      ///< θ̇ of the cruise [rad/s], > 0
    double ramp_time = 1.0;       ///< [s] >= 0, shortened to fit short, fast manoeuvres
    double command_period = 0.01;  ///< [s] > 0 between set-points
    double max_rotor_speed = 0.0;  ///< [rad/s] >= 0; 0: no limit
    double settle = 1.0;           ///< [s] >= 0 at rest before the rest is measured
    double actuator_time_constant = 0.0;  ///< τ [s] >= 0 of the rotors' lag to feed forward
    int corrections = 0;                  ///< corrective manoeuvres after a plan, >= 0
    double correction_tolerance = 1e-5;   ///< [m] > 0: a smaller miss on the plane is not corrected
    double correction_heading_tolerance = 1e-3;  ///< [rad] > 0, likewise for the heading
    double correction_tilt_tolerance = 1e-4;  ///< [rad] > 0: the contact this close to the pole is on it
    int correction_steps = 1;                 ///< figure eights of a correction, >= 1
    double max_clock_step = kDefaultMaxClockStep;  ///< [s] > 0: a longer step of time is a jump
  };

  /// Something to log: what happened, or why something was refused.
  struct Report {
    enum class Kind { kInfo, kWarning, kRefusal };
    Kind kind;
    std::string text;
  };

  /// What to do after a step.
  struct Output {
    ManoeuvreState state = ManoeuvreState::kIdle;
    std::optional<RotorSpeeds> set_point;  ///< [rad/s] to command now; none: command nothing
    std::optional<ManoeuvreVerdict> ended;  ///< the execution that ended at this step
    std::optional<ManoeuvreProgress> progress;  ///< the execution in progress after this step
    double clock_jump = 0.0;  ///< [s] time jumped by this much before the step; 0: it did not
    std::vector<Report> reports;
  };

  /// @throw std::invalid_argument naming the first parameter out of its range, with its value.
  explicit ManoeuvreExecutive(const Parameters& parameters);

  /// Keeps the solutions of a plan request (shortest first) as the plans execute() chooses from;
  /// corrections are planned with the request's k and radius limit. A result without solutions
  /// keeps the previous plans.
  void offerPlans(const PlanRequest& request, const PlanResult& result);

  /// Asks to execute plan `index` of the last offered ones, from the next step. Refused while an
  /// execution is in progress or requested, or for an index beyond the plans.
  /// @return empty if accepted, else the refusal.
  std::string execute(std::uint32_t index);

  /// Ends the execution in progress or requested at `now` [ns], with the latest measurement of
  /// the sphere: kCanceled, its miss as measured. The next step commands the rotors to rest (one
  /// zero set-point) unless a new execution starts there. @throw std::logic_error if there is
  /// none to cancel.
  ManoeuvreVerdict cancel(Nanoseconds now, const std::optional<RestMeasurement>& measurement);

  /// The step at `now` [ns] with the latest measurement of the sphere (none before the first).
  /// A requested execution starts here, its goal the plan's target taken from the measured rest
  /// (the zero state if none). A jump of the clock (max_clock_step) shifts the manoeuvre's start
  /// with it: the schedule goes on from where it was.
  Output step(Nanoseconds now, const std::optional<RestMeasurement>& measurement);

  ManoeuvreState state() const { return state_; }
  /// Whether an execution is in progress or requested (what cancel() ends).
  bool executing() const { return manoeuvre_.has_value() || requested_.has_value(); }
  /// Whether the next step has something to do: executing(), or the rotors to bring to rest
  /// after a cancel.
  bool busy() const { return executing() || stopping_; }
  /// "executing plan I, C of N corrections" while executing, else "bringing the rotors to rest",
  /// "idle" or "waiting for a plan request".
  std::string describe() const;
  std::size_t plansAvailable() const { return plans_.size(); }
  unsigned long executions() const { return executions_; }
  unsigned long correctionsMade() const { return corrections_made_; }
  /// How far the last execution to end (ManoeuvreVerdict::miss) was from its goal; none before
  /// the first.
  const std::optional<Miss>& lastMiss() const { return last_miss_; }
  const Parameters& parameters() const { return parameters_; }

 private:
  struct Manoeuvre {
    std::uint32_t index;
    SetPointSchedule schedule;
    double duration;  ///< [s] of the schedule
    Nanoseconds start;
    RestPose goal;
    int corrections_left;
    ManoeuvreState tracing;  ///< kExecuting, kReturningToPole or kCorrecting
  };

  void followClock(Nanoseconds now, Output& out);
  /// The goal of plan `index` executed from the measured rest (the zero state if none).
  RestPose goalOf(std::uint32_t index, const std::optional<RestMeasurement>& measured) const;
  void begin(std::uint32_t index, Nanoseconds now, const std::optional<RestMeasurement>& measured,
             Output& out);
  /// Starts tracing `curve` n times toward `goal`; false (refused in out) if it cannot.
  bool startFigureEight(std::uint32_t index, const FigureEight& curve, int steps,
                        const RestPose& goal, int corrections_left, ManoeuvreState tracing,
                        Nanoseconds now, Output& out);
  void startPoleReturn(const PoleReturnArc& arc, Nanoseconds now, Output& out);
  /// curve_rate, lowered (reported) so that a manoeuvre whose rotors peak at peak_at_unit_rate
  /// [rad/s] at θ̇ = 1 rad/s stays within max_rotor_speed.
  double limitedCurveRate(double peak_at_unit_rate, Output& out) const;
  CurveTiming curveTiming(int steps, double rate) const;
  /// After the manoeuvre has settled: starts a correction if one is due and possible.
  bool startCorrection(Nanoseconds now, const std::optional<RestMeasurement>& measured,
                       Output& out);
  bool planCorrection(Nanoseconds now, const RestMeasurement& measured, Output& out);
  void finish(Nanoseconds now, const std::optional<RestMeasurement>& measured, Output& out);
  /// The verdict on the execution of plan `index` toward `goal` (keeps its miss as lastMiss()):
  /// "plan <index> <what>, <miss>".
  ManoeuvreVerdict verdict(ManoeuvreEnd end, std::uint32_t index, const RestPose& goal,
                           int corrections, double elapsed,
                           const std::optional<RestMeasurement>& measured, const std::string& what);
  /// The verdict on the manoeuvre in progress at now.
  ManoeuvreVerdict verdictNow(ManoeuvreEnd end, Nanoseconds now,
                              const std::optional<RestMeasurement>& measured,
                              const std::string& what);
  /// Corrective manoeuvres made so far in the execution of `manoeuvre`.
  int correctionsIn(const Manoeuvre& manoeuvre) const;
  Miss missFrom(const RestPose& goal, const std::optional<RestMeasurement>& measured) const;
  /// [s] since the manoeuvre started at now.
  double elapsed(Nanoseconds now) const;

  Parameters parameters_;
  ClockJumpDetector clock_;
  Nanoseconds last_step_ = 0;
  double plan_k_ = 0.0;
  int plan_steps_ = 0;
  double plan_max_radius_ = 0.0;       ///< [R]
  std::vector<FigureEight> plans_;     ///< in units of R
  std::vector<PlanTarget> targets_;    ///< what each of plans_ reaches from the zero state
  std::optional<std::uint32_t> requested_;
  std::optional<Manoeuvre> manoeuvre_;
  Nanoseconds began_ = 0;  ///< when the execution in progress started
  bool stopping_ = false;  ///< canceled: the next step commands the rotors to rest
  ManoeuvreState state_ = ManoeuvreState::kIdle;
  unsigned long executions_ = 0;
  unsigned long corrections_made_ = 0;
  std::optional<Miss> last_miss_;
};

}  // namespace spherical_robots::rotor
