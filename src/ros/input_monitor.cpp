#include "spherical_robots/ros/input_monitor.hpp"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/console.h>

#include <utility>

namespace spherical_robots {

InputMonitor::InputMonitor(std::string topic, double timeout)
    : topic_(std::move(topic)), timeout_(timeout) {}

void InputMonitor::accept(const ros::Time& now) {
  last_accepted_ = now;
  ++accepted_;
}

void InputMonitor::reject(const std::string& reason) {
  ++rejected_;
  last_reason_ = reason;
  const ros::WallTime now = ros::WallTime::now();
  if ((now - last_log_).toSec() >= 1.0) {
    last_log_ = now;
    ROS_WARN_STREAM("Ignoring a message on " << topic_ << " (" << rejected_
                                             << " rejected so far): " << reason);
  }
}

bool InputMonitor::fresh(const ros::Time& now) const {
  if (accepted_ == 0) return false;
  const double age = (now - last_accepted_).toSec();
  return age >= 0.0 && age <= timeout_;
}

void InputMonitor::report(diagnostic_updater::DiagnosticStatusWrapper& status, const ros::Time& now) {
  using diagnostic_msgs::DiagnosticStatus;
  status.add(topic_ + " accepted", accepted_);
  status.add(topic_ + " rejected", rejected_);
  if (!last_reason_.empty()) status.add(topic_ + " last rejection", last_reason_);
  if (accepted_ == 0) {
    status.mergeSummary(DiagnosticStatus::WARN, "no message yet on " + topic_);
  } else {
    status.add(topic_ + " age [s]", (now - last_accepted_).toSec());
    if (!fresh(now)) status.mergeSummaryf(DiagnosticStatus::WARN, "%s stale", topic_.c_str());
  }
  if (rejected_ > rejected_at_last_report_) {
    status.mergeSummaryf(DiagnosticStatus::WARN, "%lu bad messages on %s",
                         rejected_ - rejected_at_last_report_, topic_.c_str());
  }
  rejected_at_last_report_ = rejected_;
}

}  // namespace spherical_robots
