#pragma once
// Book-keeping for one input topic of a node: when the last good message came, how many were
// rejected and why, and how the node's health follows the rejections (core/input_health.hpp: WARN
// while they continue, ERROR past a rate, OK after good input has flowed again). A node never
// dies on a bad message; it logs it (throttled), keeps its last good state, and this monitor
// reports it on /diagnostics.

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <ros/time.h>

#include <string>

#include "spherical_robots/core/input_health.hpp"

namespace spherical_robots {

/// Why a message stamped `stamp` cannot be trusted at ROS time `now`: unset (0), or more than
/// `tolerance` [s] ahead of or behind the clock; empty if it can.
std::string stampProblem(const ros::Time& stamp, const ros::Time& now, double tolerance);

/// The diagnostic_msgs/DiagnosticStatus level of a health level.
unsigned char statusLevel(HealthLevel level);

class InputMonitor {
 public:
  /// @param topic resolved name for logs and diagnostics, @param timeout [s] > 0 after which the
  /// last good message is stale.
  InputMonitor(std::string topic, double timeout, InputHealthPolicy policy = {});

  /// A good message arrived at `now` (ROS time).
  void accept(const ros::Time& now);
  /// A bad message arrived; logs the reason (at most once a second) and counts it.
  void reject(const std::string& reason);

  /// A good message arrived within the timeout before `now` (false before the first one, and after
  /// ROS time jumped back past it).
  bool fresh(const ros::Time& now) const;

  /// Adds this input's figures to `status`, raises it to WARN if the input is not fresh, and
  /// escalates it as reportRejections().
  void report(diagnostic_updater::DiagnosticStatusWrapper& status, const ros::Time& now);
  /// Adds the rejection rate and raises `status` to WARN or ERROR while the health policy says
  /// so, naming the topic, the rate and the last reason.
  void reportRejections(diagnostic_updater::DiagnosticStatusWrapper& status);

  const std::string& topic() const { return topic_; }
  /// The figures report() adds, for a node that reports them under its own names and levels.
  unsigned long accepted() const { return accepted_; }
  unsigned long rejected() const { return rejected_; }
  /// The reason given with the last rejected message; empty before the first one.
  const std::string& lastReason() const { return health_.lastReason(); }
  /// The health level the rejections give now (wall time).
  HealthLevel health();

 private:
  std::string topic_;
  double timeout_;
  InputHealth health_;
  ros::Time last_accepted_;
  unsigned long accepted_ = 0;
  unsigned long rejected_ = 0;
  ros::WallTime last_log_;
};

}  // namespace spherical_robots
