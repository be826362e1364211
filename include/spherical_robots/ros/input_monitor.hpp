#pragma once
// Book-keeping for one input topic of a node: when the last good message came, how many were
// rejected and why. A node never dies on a bad message; it logs it (throttled), keeps its last
// good state, and this monitor reports it on /diagnostics.

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <ros/time.h>

#include <string>

namespace spherical_robots {

class InputMonitor {
 public:
  /// @param topic resolved name for logs and diagnostics, @param timeout [s] > 0 after which the
  /// last good message is stale.
  InputMonitor(std::string topic, double timeout);

  /// A good message arrived at `now` (ROS time).
  void accept(const ros::Time& now);
  /// A bad message arrived; logs the reason (at most once a second) and counts it.
  void reject(const std::string& reason);

  /// A good message arrived within the timeout before `now` (false before the first one, and after
  /// ROS time jumped back past it).
  bool fresh(const ros::Time& now) const;

  /// Adds this input's figures to `status` and raises it to WARN if the input is not fresh or
  /// messages were rejected since the last report.
  void report(diagnostic_updater::DiagnosticStatusWrapper& status, const ros::Time& now);

  const std::string& topic() const { return topic_; }
  /// The figures report() adds, for a node that reports them under its own names and levels.
  unsigned long accepted() const { return accepted_; }
  unsigned long rejected() const { return rejected_; }
  /// The reason given with the last rejected message; empty before the first one.
  const std::string& lastReason() const { return last_reason_; }

 private:
  std::string topic_;
  double timeout_;
  ros::Time last_accepted_;
  unsigned long accepted_ = 0;
  unsigned long rejected_ = 0;
  unsigned long rejected_at_last_report_ = 0;
  std::string last_reason_;
  ros::WallTime last_log_;
};

}  // namespace spherical_robots
