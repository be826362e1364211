#pragma once
// The rate of one of a node's publications against the rate the node is configured for, on
// /diagnostics as its own status "<node>: <topic> rate", e.g. "sphere/terrain_plant:
// sphere/terrain_state rate" (docs/nodes.md, "Diagnostics"). A diagnostic_updater task over
// core/publication_rate.hpp, which counts as diagnostic_updater::FrequencyStatus does but at the
// time the node works at (its clock: the latest step in lock-step, ROS time otherwise), not at
// ros::Time::now(): rates of simulated time in lock-step and free, of wall time with clock:=wall.

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/time.h>

#include <functional>
#include <string>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/core/publication_rate.hpp"

namespace spherical_robots {

/// ~rate_tolerance: the fraction by which a measured rate may miss its node's configured one
/// (default 0.1). @throw std::invalid_argument unless 0 <= value < 1, naming it and the limit.
double loadRateTolerance(const config::ParameterSource& source);

class TopicRate : public diagnostic_updater::DiagnosticTask {
 public:
  /// The time the node works at.
  using Clock = std::function<ros::Time()>;
  /// Whether the node has publications to make now (e.g. a manoeuvre is running).
  using Expected = std::function<bool()>;

  /// @param topic resolved name, @param rate [Hz] > 0 the node is configured for, @param tolerance
  /// as loadRateTolerance, @param expected empty: always.
  /// @throw std::invalid_argument on a bad rate or tolerance, naming the topic.
  TopicRate(const std::string& topic, double rate, double tolerance, Clock clock,
            Expected expected = {});

  /// Adds this status to `updater`, which must not outlive it.
  void addTo(diagnostic_updater::Updater& updater) { updater.add(*this); }
  /// One message was published.
  void tick() { rate_.tick(); }
  void run(diagnostic_updater::DiagnosticStatusWrapper& status) override;

 private:
  PublicationRate rate_;
  Clock clock_;
  Expected expected_;
};

}  // namespace spherical_robots
