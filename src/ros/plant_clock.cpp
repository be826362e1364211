#include "spherical_robots/ros/plant_clock.hpp"

#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/ros/conversions.hpp"

#include <ros/init.h>

#include <stdexcept>

#include "spherical_robots/ros/lockstep_clock.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
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

namespace {

enum class ClockMode { kLockstep, kFree, kRos };

ClockMode clockModeFromString(const std::string& name) {
  if (name == "lockstep") return ClockMode::kLockstep;
  if (name == "free") return ClockMode::kFree;
  if (name == "ros") return ClockMode::kRos;
  throw std::invalid_argument("unknown clock mode (lockstep | free | ros)");
}

double nonNegativeSpeedup(const ros::NodeHandle& pnh, double fallback) {
  const double speedup = numberParam(pnh, "speedup", fallback);
  if (speedup < 0.0)
    throw std::invalid_argument("parameter " + pnh.resolveName("speedup") + " = " +
                                std::to_string(speedup) + " must be >= 0");
  return speedup;
}

}  // namespace

std::unique_ptr<PlantClock> makePlantClock(ros::NodeHandle nh, const ros::NodeHandle& pnh,
                                           double step, double default_pace,
                                           PlantClock::Tick tick, const ros::Publisher& state,
                                           const ros::Subscriber& actuators) {
  const ClockMode mode = parsedParam(pnh, "clock", "ros", clockModeFromString);
  const int expected_subscribers = static_cast<int>(numberParam(pnh, "wait_for_subscribers", 1.0));
  const double start_timeout = positiveParam(pnh, "start_timeout", 10.0);
  PlantClock::Ready ready = [state, actuators, expected_subscribers] {
    return static_cast<int>(state.getNumSubscribers()) >= expected_subscribers &&
           actuators.getNumPublishers() > 0;
  };
  switch (mode) {
    case ClockMode::kLockstep: {
      LockstepClock::Settings settings;
      settings.step = step;
      settings.speedup = nonNegativeSpeedup(pnh, 0.0);
      settings.leader = stringParam(pnh, "lockstep_leader", "");
      settings.name = pnh.getNamespace();
      if (!settings.leader.empty() && settings.leader.front() != '/')
        throw std::invalid_argument("parameter " + pnh.resolveName("lockstep_leader") + " = \"" +
                                    settings.leader + "\" must be an absolute namespace (\"/sphere\")");
      // A follower drops its own silent participant before the leader would drop the follower.
      settings.timeout = positiveParam(pnh, "lockstep_timeout", settings.leader.empty() ? 2.0 : 1.0);
      settings.start_timeout = start_timeout;
      settings.participants = lockstepParticipants(nh);
      settings.subscriptions = {actuators.getTopic()};
      return std::make_unique<LockstepClock>(nh, settings, std::move(tick), std::move(ready));
    }
    case ClockMode::kFree: {
      const double pace = nonNegativeSpeedup(pnh, default_pace);
      if (!(pace > 0.0))
        throw std::invalid_argument("parameter " + pnh.resolveName("speedup") +
                                    " must be > 0 with clock free (the pace of simulated time)");
      return std::make_unique<SimClock>(nh, step, pace, std::move(tick), std::move(ready),
                                        start_timeout);
    }
    case ClockMode::kRos:
      return std::make_unique<SimClock>(nh, step, 0.0, std::move(tick));
  }
  throw std::logic_error("unhandled clock mode");
}

}  // namespace spherical_robots
