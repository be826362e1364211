#include "spherical_robots/ros/input_monitor.hpp"

#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/ros/conversions.hpp"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/console.h>

#include <sstream>
#include <utility>

namespace spherical_robots {
namespace {

// Wall time: the rate of bad messages is the sender's, and a stray /clock must not reset it.
double wallSeconds() { return ros::WallTime::now().toSec(); }

}  // namespace

unsigned char statusLevel(HealthLevel level) {
  using diagnostic_msgs::DiagnosticStatus;
  switch (level) {
    case HealthLevel::kOk: return DiagnosticStatus::OK;
    case HealthLevel::kWarn: return DiagnosticStatus::WARN;
    case HealthLevel::kError: return DiagnosticStatus::ERROR;
  }
  return DiagnosticStatus::ERROR;
}

std::string stampProblem(const ros::Time& stamp, const ros::Time& now, double tolerance) {
  if (stamp.isZero()) return "stamp is 0 (unset)";
  const double ahead = (stamp - now).toSec();
  if (ahead > tolerance || ahead < -tolerance) {
    std::ostringstream problem;
    problem << "stamp " << stamp.toSec() << " s is " << (ahead > 0.0 ? ahead : -ahead) << " s "
            << (ahead > 0.0 ? "ahead of" : "behind") << " the clock (" << now.toSec()
            << " s; max_stamp_skew " << tolerance << " s)";
    return problem.str();
  }
  return {};
}

InputMonitor::InputMonitor(std::string topic, double timeout, InputHealthPolicy policy)
    : topic_(std::move(topic)), timeout_(timeout), health_(policy) {}

void InputMonitor::accept(const ros::Time& now) {
  last_accepted_ = now;
  ++accepted_;
  health_.accepted(wallSeconds());
}

void InputMonitor::reject(const std::string& reason) {
  ++rejected_;
  health_.rejected(wallSeconds(), reason);
  const ros::WallTime now = ros::WallTime::now();
  if ((now - last_log_).toSec() >= 1.0) {
    last_log_ = now;
    ROS_WARN_STREAM("Ignoring a message on " << topic_ << " (" << rejected_
                                             << " rejected so far): " << reason);
  }
}

bool InputMonitor::fresh(const ros::Time& now) const {
  return accepted_ != 0 && withinTimeout(nanosecondsOf(last_accepted_), nanosecondsOf(now), timeout_);
}

HealthLevel InputMonitor::health() { return health_.level(wallSeconds()); }

void InputMonitor::reportRejections(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const double t = wallSeconds();
  const double rate = health_.rejectionRate(t);
  status.add(topic_ + " rejected per second", rate);
  const HealthLevel level = health_.level(t);
  if (level == HealthLevel::kOk) return;
  std::ostringstream summary;
  summary << "bad messages on " << topic_ << " (" << rate << "/s, " << rejected_
          << " in all): " << health_.lastReason();
  status.mergeSummary(statusLevel(level), summary.str());
}

void InputMonitor::report(diagnostic_updater::DiagnosticStatusWrapper& status, const ros::Time& now) {
  using diagnostic_msgs::DiagnosticStatus;
  status.add(topic_ + " accepted", accepted_);
  status.add(topic_ + " rejected", rejected_);
  if (!lastReason().empty()) status.add(topic_ + " last rejection", lastReason());
  if (accepted_ == 0) {
    status.mergeSummary(DiagnosticStatus::WARN, "no message yet on " + topic_);
  } else {
    status.add(topic_ + " age [s]", (now - last_accepted_).toSec());
    if (!fresh(now)) status.mergeSummaryf(DiagnosticStatus::WARN, "%s stale", topic_.c_str());
  }
  reportRejections(status);
}

}  // namespace spherical_robots
