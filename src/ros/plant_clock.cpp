#include "spherical_robots/ros/plant_clock.hpp"

#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/ros/conversions.hpp"

#include <ros/init.h>

#include <stdexcept>

#include "spherical_robots/ros/lockstep_clock.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/sim_clock.hpp"

namespace spherical_robots {

bool periodDue(const ros::Time& last, const ros::Time& now, double period) {
  return periodDue(nanosecondsOf(last), nanosecondsOf(now), period);
}

void PlantClock::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.add("clock mode", mode());
  status.add("real-time factor", realTimeFactor());
}

void PlantClock::finish() { ros::shutdown(); }


std::unique_ptr<PlantClock> makePlantClock(ros::NodeHandle nh, const ros::NodeHandle& pnh,
                                           const config::PlantLoopParameters& parameters,
                                           PlantClock::Tick tick, const ros::Publisher& state,
                                           const ros::Subscriber& actuators) {
  const int expected_subscribers = parameters.wait_for_subscribers;
  PlantClock::Ready ready = [state, actuators, expected_subscribers] {
    return static_cast<int>(state.getNumSubscribers()) >= expected_subscribers &&
           actuators.getNumPublishers() > 0;
  };
  switch (parameters.clock) {
    case config::ClockMode::kLockstep: {
      LockstepClock::Settings settings;
      settings.step = parameters.step;
      settings.speedup = parameters.speedup;
      settings.leader = parameters.lockstep_leader;
      settings.name = pnh.getNamespace();
      settings.timeout = parameters.lockstep_timeout;
      settings.start_timeout = parameters.start_timeout;
      settings.clock_rate = parameters.clock_rate;
      settings.loop_cpu = parameters.loop_cpu;
      settings.participants = lockstepParticipants(nh);
      settings.subscriptions = {actuators.getTopic()};
      return std::make_unique<LockstepClock>(nh, settings, std::move(tick), std::move(ready));
    }
    case config::ClockMode::kFree:
      return std::make_unique<SimClock>(nh, parameters.step, parameters.speedup, std::move(tick),
                                        std::move(ready), parameters.start_timeout);
    case config::ClockMode::kRos:
      return std::make_unique<SimClock>(nh, parameters.step, 0.0, std::move(tick));
  }
  throw std::logic_error("unhandled clock mode");
}

}  // namespace spherical_robots
