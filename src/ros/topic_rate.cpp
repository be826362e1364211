#include "spherical_robots/ros/topic_rate.hpp"

#include <sstream>
#include <stdexcept>
#include <utility>

#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/input_monitor.hpp"

namespace spherical_robots {

namespace {

// Without the leading '/', as diagnostic_updater names the node before it ("sphere/terrain_plant:
// sphere/terrain_state rate"), which the analyzers of config/diagnostics/ match.
std::string taskName(const std::string& topic) {
  return (!topic.empty() && topic.front() == '/' ? topic.substr(1) : topic) + " rate";
}

PublicationRate makeRate(const std::string& topic, double rate, double tolerance) {
  try {
    return PublicationRate(rate, tolerance);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("rate of " + topic + ": " + e.what());
  }
}

}  // namespace

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

TopicRate::TopicRate(const std::string& topic, double rate, double tolerance, Clock clock,
                     Expected expected)
    : DiagnosticTask(taskName(topic)),
      rate_(makeRate(topic, rate, tolerance)),
      clock_(std::move(clock)),
      expected_(std::move(expected)) {}

void TopicRate::run(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const ros::Time now = clock_();
  const PublicationRate::Report report =
      rate_.report(nanosecondsOf(now), !expected_ || expected_());
  status.summary(statusLevel(report.level), report.message);
  // FrequencyStatus's keys, which tools and people know.
  status.add("Events in window", report.events);
  status.add("Events since startup", report.total);
  status.add("Duration of window (s)", report.window);
  // The node's time, which may differ from ros::Time::now() (topic_rate.hpp).
  status.add("End of window (s)", now.toSec());
  if (report.frequency) status.add("Actual frequency (Hz)", *report.frequency);
  status.add("Target frequency (Hz)", rate_.target());
  status.add("Minimum acceptable frequency (Hz)", rate_.target() * (1.0 - rate_.tolerance()));
  status.add("Maximum acceptable frequency (Hz)", rate_.target() * (1.0 + rate_.tolerance()));
}

}  // namespace spherical_robots
