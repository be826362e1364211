#pragma once
// The rate of one of a node's publications against the rate the node is configured for, on
// /diagnostics as its own status "<node>: <topic> rate", e.g. "sphere/terrain_plant:
// sphere/terrain_state rate" (docs/nodes.md, "Diagnostics").
// diagnostic_updater::FrequencyStatus does the counting, over its last 5 reports, in ROS time:
// simulated time in lock-step and free (where the nodes' rates are rates of simulated time, so
// a run paced at 20 x real time still reports 100 Hz, not 2,000) and wall time with clock:=wall.
// What FrequencyStatus alone gets wrong, this adds: it calls a stopped clock (lock-step before
// time starts, paused, or after the scenario's end) "No events recorded" at ERROR, it measures
// across a jump back of ROS time, and it expects events from a node that has nothing to send (a
// planner between manoeuvres). In those cases this reports OK, says why, and measures afresh
// once time runs again and publications are expected.

#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/update_functions.h>
#include <ros/node_handle.h>
#include <ros/time.h>

#include <functional>
#include <string>

#include "spherical_robots/config/parameter_source.hpp"

namespace spherical_robots {

/// ~rate_tolerance: the fraction by which a measured rate may miss its node's configured one
/// (default 0.1). @throw std::invalid_argument unless 0 <= value < 1, naming it and the limit.
double loadRateTolerance(const config::ParameterSource& source);

class TopicRate : public diagnostic_updater::DiagnosticTask {
 public:
  /// Whether the node has publications to make now (e.g. a manoeuvre is running).
  using Expected = std::function<bool()>;

  /// @param topic resolved name, @param rate [Hz] > 0 the node is configured for, @param tolerance
  /// as loadRateTolerance, @param expected empty: always.
  TopicRate(const std::string& topic, double rate, double tolerance, Expected expected = {});
  TopicRate(const TopicRate&) = delete;
  TopicRate& operator=(const TopicRate&) = delete;

  /// Adds this status to `updater`, which must not outlive it.
  void addTo(diagnostic_updater::Updater& updater) { updater.add(*this); }
  /// One message was published.
  void tick() { frequency_.tick(); }
  void run(diagnostic_updater::DiagnosticStatusWrapper& status) override;

 private:
  /// Starts a fresh window at the current ROS time and reports it with `why`.
  void restart(diagnostic_updater::DiagnosticStatusWrapper& status, const std::string& why);

  double rate_;
  double tolerance_;
  diagnostic_updater::FrequencyStatus frequency_;  ///< reads rate_ through a pointer
  Expected expected_;
  ros::Time last_report_;
  bool measuring_ = false;  ///< frequency_'s window started at a report with time running
};

}  // namespace spherical_robots
