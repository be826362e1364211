#include "spherical_robots/ros/topic_rate.hpp"

#include <diagnostic_msgs/DiagnosticStatus.h>

#include <sstream>
#include <stdexcept>
#include <utility>

namespace spherical_robots {

double loadRateTolerance(const config::ParameterSource& source) {
  const double tolerance = config::nonNegativeNumber(source, "rate_tolerance", 0.1);
  if (tolerance >= 1.0) {
    std::ostringstream message;
    message << source.origin() << ": parameter 'rate_tolerance' = " << tolerance
            << ": must be < 1 (a fraction of the configured rate)";
    throw std::invalid_argument(message.str());
  }
  return tolerance;
}

namespace {

// Without the leading '/', as diagnostic_updater names the node before it ("sphere/terrain_plant:
// sphere/terrain_state rate"), which the analyzers of config/diagnostics/ match.
std::string taskName(const std::string& topic) {
  return (!topic.empty() && topic.front() == '/' ? topic.substr(1) : topic) + " rate";
}

}  // namespace

TopicRate::TopicRate(const std::string& topic, double rate, double tolerance, Expected expected)
    : DiagnosticTask(taskName(topic)),
      rate_(rate),
      tolerance_(tolerance),
      frequency_(diagnostic_updater::FrequencyStatusParam(&rate_, &rate_, tolerance_)),
      expected_(std::move(expected)) {}

void TopicRate::restart(diagnostic_updater::DiagnosticStatusWrapper& status, const std::string& why) {
  frequency_.clear();
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, why);
  status.add("Target frequency (Hz)", rate_);
  status.add("Tolerance", tolerance_);
}

void TopicRate::run(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const ros::Time now = ros::Time::now();
  const ros::Time last = last_report_;
  const bool was_measuring = measuring_;
  last_report_ = now;
  measuring_ = false;
  if (expected_ && !expected_()) return restart(status, "idle: nothing to publish");
  if (now == last) return restart(status, "ROS time stopped (not started, paused or ended)");
  if (now < last) return restart(status, "ROS time jumped back: measuring afresh");
  measuring_ = true;
  // The first window after a pause or an idle spell would count the spell as silence.
  if (!was_measuring) return restart(status, "measuring");
  frequency_.run(status);
}

}  // namespace spherical_robots
