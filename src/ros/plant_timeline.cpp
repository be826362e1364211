#include "spherical_robots/ros/plant_timeline.hpp"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/console.h>

#include <exception>

#include "spherical_robots/ros/conversions.hpp"

namespace spherical_robots {

PlantTimeline::PlantTimeline(double duration, double max_clock_step)
    : timeline_(duration, max_clock_step) {}

void PlantTimeline::tick(const ros::Time& now, const std::function<void(double elapsed)>& advance) {
  const double last_tick = stampSeconds(timeline_.lastTick());
  const LoopTimeline::Tick tick = timeline_.tick(nanosecondsOf(now));
  if (tick.advances()) {
    try {
      advance(tick.elapsed);
    } catch (const std::exception& e) {
      ++failures_;
      ROS_ERROR_STREAM_THROTTLE(1.0, "Integration failed (" << failures_ << " so far), holding the "
                                                               "last good state: " << e.what());
    }
  } else if (!tick.starts && tick.clock != ClockStep::kHold) {
    ROS_WARN_STREAM_THROTTLE(1.0, "ROS time jumped from " << last_tick << " to " << now << " s ("
                                                          << toString(tick.clock) << ", max_clock_step "
                                                          << timeline_.clock().maxStep()
                                                          << " s); holding the state");
  }
}

void PlantTimeline::resume(const ros::Time& start, const ros::Time& last_tick) {
  timeline_.resume(nanosecondsOf(start), nanosecondsOf(last_tick));
}

bool PlantTimeline::complete(const ros::Time& now) { return timeline_.complete(nanosecondsOf(now)); }

void PlantTimeline::report(diagnostic_updater::DiagnosticStatusWrapper& status,
                           const ros::Time& now) {
  status.add("time since start [s]",
             timeline_.started() ? stampSeconds(nanosecondsOf(now) - timeline_.start()) : 0.0);
  status.add("clock jumps", timeline_.clock().jumps());
  status.add("integration failures", failures_);
  if (failures_ > failures_at_last_report_)
    status.mergeSummary(diagnostic_msgs::DiagnosticStatus::ERROR, "integration failed");
  failures_at_last_report_ = failures_;
}

}  // namespace spherical_robots
