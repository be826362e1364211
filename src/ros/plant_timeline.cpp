#include "spherical_robots/ros/plant_timeline.hpp"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/console.h>

#include <exception>

#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {

PlantTimeline::PlantTimeline(double duration, double max_clock_step)
    : duration_(duration), clock_(max_clock_step) {}

PlantTimeline::PlantTimeline(const ros::NodeHandle& pnh)
    : PlantTimeline(numberParam(pnh, "duration", 0.0), positiveParam(pnh, "max_clock_step", kDefaultMaxClockStep)) {}

void PlantTimeline::tick(const ros::Time& now, const std::function<void(double elapsed)>& advance) {
  const ClockStep step = clock_.observe(now.toSec());
  if (start_.isZero()) {
    start_ = now;
  } else if (step == ClockStep::kAdvance) {
    try {
      advance((now - last_tick_).toSec());
    } catch (const std::exception& e) {
      ++failures_;
      ROS_ERROR_STREAM_THROTTLE(1.0, "Integration failed (" << failures_ << " so far), holding the "
                                                               "last good state: " << e.what());
    }
  } else if (step != ClockStep::kHold) {
    ROS_WARN_STREAM_THROTTLE(1.0, "ROS time jumped from " << last_tick_ << " to " << now << " s ("
                                                          << toString(step) << ", max_clock_step "
                                                          << clock_.maxStep()
                                                          << " s); holding the state");
  }
  last_tick_ = now;
}

bool PlantTimeline::complete(const ros::Time& now) {
  if (!finished_ && duration_ > 0.0 && !start_.isZero() &&
      (now - start_).toSec() >= duration_ - 1e-9)
    finished_ = true;
  return finished_;
}

void PlantTimeline::report(diagnostic_updater::DiagnosticStatusWrapper& status,
                           const ros::Time& now) {
  status.add("time since start [s]", start_.isZero() ? 0.0 : (now - start_).toSec());
  status.add("clock jumps", clock_.jumps());
  status.add("integration failures", failures_);
  if (failures_ > failures_at_last_report_)
    status.mergeSummary(diagnostic_msgs::DiagnosticStatus::ERROR, "integration failed");
  failures_at_last_report_ = failures_;
}

}  // namespace spherical_robots
