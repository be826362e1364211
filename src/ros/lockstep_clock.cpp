#include "spherical_robots/ros/lockstep_clock.hpp"

#include <boost/make_shared.hpp>
#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/callback_queue.h>
#include <ros/console.h>
#include <ros/init.h>
#include <ros/this_node.h>
#include <rosgraph_msgs/Clock.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "spherical_robots/LockstepStep.h"
#include "spherical_robots/ros/conversions.hpp"

namespace spherical_robots {
namespace {

/// Runs a function from a callback queue: the next step is queued, not called, so that the
/// acknowledgements, messages and services queued meanwhile are served in between.
class QueuedCall : public ros::CallbackInterface {
 public:
  explicit QueuedCall(std::function<void()> call) : call_(std::move(call)) {}
  CallResult call() override {
    call_();
    return Success;
  }

 private:
  std::function<void()> call_;
};

ros::Time fromNanoseconds(std::int64_t ns) {
  ros::Time t;
  t.fromNSec(static_cast<std::uint64_t>(ns));
  return t;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "none" : text;
}

}  // namespace

LockstepClock::LockstepClock(ros::NodeHandle nh, Settings settings, Tick tick, Ready ready)
    : settings_(std::move(settings)), tick_(std::move(tick)), ready_(std::move(ready)),
      sequencer_(ros::this_node::getName(), settings_.participants, settings_.timeout),
      inputs_(settings_.subscriptions), queue_(nh.getCallbackQueue()),
      created_wall_(ros::WallTime::now()) {
  if (!(settings_.step > 0.0) || !std::isfinite(settings_.step) ||
      !(settings_.speedup >= 0.0) || !std::isfinite(settings_.speedup)) {
    std::ostringstream what;
    what << "lock-step clock: step = " << settings_.step << " s must be > 0, speedup = "
         << settings_.speedup << " finite and >= 0";
    throw std::invalid_argument(what.str());
  }
  if (!ros::Time::isSimTime())
    throw std::invalid_argument("lock-step clock publishes /clock, but /use_sim_time is not true, "
                                "so no node would follow it");
  if (!queue_) queue_ = ros::getGlobalCallbackQueue();
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  request_pub_ = nh.advertise<spherical_robots::LockstepStep>("lockstep/step", 100);
  ack_sub_ = nh.subscribe("lockstep/ack", 100, &LockstepClock::onAck, this, hints);
  if (settings_.leader.empty()) {
    clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 100);
    pause_srv_ = nh.advertiseService("lockstep/pause", &LockstepClock::pause, this);
    resume_srv_ = nh.advertiseService("lockstep/resume", &LockstepClock::resume, this);
    step_srv_ = nh.advertiseService("lockstep/step_once", &LockstepClock::stepOnce, this);
  } else {
    leader_nh_ = ros::NodeHandle(settings_.leader);
  }
  poll_timer_ = nh.createWallTimer(ros::WallDuration(0.05), &LockstepClock::poll, this);
  pace_timer_ = nh.createWallTimer(
      ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) { runStep(); }, true, false);
  ROS_INFO_STREAM("Lock-step " << (settings_.leader.empty() ? "/clock" : "time of " + settings_.leader)
                  << ": " << settings_.step << " s per step, "
                  << (!settings_.leader.empty() ? std::string("as its leader asks")
                      : settings_.speedup > 0.0 ? "at most " + std::to_string(settings_.speedup) +
                                                      "x real time"
                                                : std::string("as fast as the participants answer"))
                  << "; participants " << joined(settings_.participants) << ", dropped after "
                  << settings_.timeout << " s of silence");
}

void LockstepClock::onAck(const ros::MessageEvent<spherical_robots::LockstepAck const>& event) {
  const spherical_robots::LockstepAck& ack = *event.getConstMessage();
  const std::string& sender = event.getPublisherName();
  if (ack.stamp.isZero()) {
    if (!sequencer_.sentBy(sender, ack.participant)) {
      ++forged_;
      ROS_WARN_STREAM_THROTTLE(1.0, "lock-step: ignoring a join request for " << ack.participant
                                                                              << " sent by " << sender);
    } else if (sequencer_.join(ack.participant)) {
      ROS_INFO_STREAM("lock-step: " << ack.participant << " joined");
    }
    return;
  }
  const AckOutcome outcome = sequencer_.acknowledge(sender, ack.participant, nanosecondsOf(ack.stamp),
                                                    ack.published, nanosecondsOf(ack.next));
  if (outcome == AckOutcome::kAccepted) {
    pump();
    return;
  }
  ++(outcome == AckOutcome::kForged ? forged_ : unexpected_);
  ROS_WARN_STREAM_THROTTLE(1.0, "lock-step: ignoring an acknowledgement (" << toString(outcome)
                                    << ") of " << ack.stamp << " s naming " << ack.participant
                                    << " from " << sender);
}

void LockstepClock::poll(const ros::WallTimerEvent&) {
  const double wall = ros::WallTime::now().toSec();
  if (!started_) {
    const double waited = (ros::WallTime::now() - created_wall_).toSec();
    const bool ready = sequencer_.allExpectedJoined() && ready_();
    if (!ready && waited < settings_.start_timeout) return;
    if (ready)
      ROS_INFO_STREAM("Starting lock-step time after " << waited << " s of wall time");
    else
      ROS_WARN_STREAM("Starting lock-step time without every participant or subscriber after "
                      << settings_.start_timeout << " s");
    started_ = true;
    if (settings_.leader.empty()) {
      schedule();
    } else {
      // Asked to join only now, so the leader never waits for a stack that cannot answer yet.
      leader_link_ = std::make_unique<LockstepParticipant>(
          leader_nh_, ros::NodeHandle(settings_.name), std::vector<ros::Subscriber>{},
          [this](const ros::Time& t) -> std::optional<LockstepParticipant::Done> {
            runStepAt(t);
            return std::nullopt;
          });
    }
    return;
  }
  if (const auto dropped = sequencer_.dropSilent(wall)) {
    dropped_.push_back(*dropped);
    ROS_ERROR_STREAM("lock-step: participant " << *dropped << " did not answer for "
                     << settings_.timeout << " s of wall time at " << now_
                     << " s: dropped, simulated time goes on without it until it rejoins");
    pump();
  }
  if (awaiting_inputs_ && (ros::WallTime::now() - inputs_since_).toSec() > settings_.timeout) {
    ROS_ERROR_STREAM("lock-step: the plant's inputs " << joined(inputs_.missing())
                     << " did not arrive within " << settings_.timeout << " s at " << now_
                     << " s; stepping on without them");
    awaiting_inputs_ = false;
    endStep();
  }
}

void LockstepClock::schedule() {
  if (finished_ || scheduled_ || sequencer_.stepInProgress()) return;
  if (paused_ && single_steps_ == 0) return;
  if (single_steps_ > 0) --single_steps_;
  scheduled_ = true;
  if (settings_.speedup > 0.0 && !first_step_.isZero()) {
    const double due = (now_ + ros::Duration(settings_.step) - first_step_).toSec() / settings_.speedup;
    const double ahead = due - (ros::WallTime::now() - first_step_wall_).toSec();
    if (ahead > 0.0) {
      pace_timer_.setPeriod(ros::WallDuration(ahead));
      pace_timer_.start();
      return;
    }
  }
  queue_->addCallback(boost::make_shared<QueuedCall>([this] { runStep(); }));
}

void LockstepClock::runStep() {
  scheduled_ = false;
  pace_timer_.stop();
  runStepAt(now_ + ros::Duration(settings_.step));
}

void LockstepClock::runStepAt(const ros::Time& t) {
  now_ = t;
  if (first_step_.isZero()) {
    first_step_ = now_;
    first_step_wall_ = ros::WallTime::now();
  }
  if (settings_.leader.empty()) {
    rosgraph_msgs::Clock clock;
    clock.clock = now_;
    clock_pub_.publish(clock);
  }
  const std::vector<std::string> published = tick_(now_);
  sequencer_.beginStep(nanosecondsOf(now_), published, ros::WallTime::now().toSec());
  pump();
}

void LockstepClock::pump() {
  while (const auto request = sequencer_.nextRequest(ros::WallTime::now().toSec())) {
    if (request->participant == sequencer_.owner()) {
      inputs_.expect(request->inputs);
      awaiting_inputs_ = true;
      inputs_since_ = ros::WallTime::now();
      finishIfInputsIn();
      return;
    }
    spherical_robots::LockstepStep step;
    step.stamp = fromNanoseconds(request->stamp);
    step.participant = request->participant;
    for (const PublishedTopic& input : request->inputs) {
      step.inputs.push_back(input.topic);
      step.input_stamps.push_back(fromNanoseconds(input.stamp));
    }
    request_pub_.publish(step);
    return;
  }
}

void LockstepClock::received(const std::string& topic, const ros::Time& stamp) {
  inputs_.received(topic, nanosecondsOf(stamp));
  if (awaiting_inputs_) finishIfInputsIn();
}

void LockstepClock::finishIfInputsIn() {
  if (!inputs_.satisfied()) return;
  awaiting_inputs_ = false;
  endStep();
}

void LockstepClock::endStep() {
  sequencer_.endStep();
  if (leader_link_)
    leader_link_->answer({{}, now_ + ros::Duration(settings_.step)});
  else
    schedule();
}

bool LockstepClock::pause(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  paused_ = true;
  single_steps_ = 0;
  ROS_INFO_STREAM("lock-step: paused at " << now_ << " s");
  return true;
}

bool LockstepClock::resume(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  paused_ = false;
  ROS_INFO_STREAM("lock-step: resumed at " << now_ << " s");
  if (started_) schedule();
  return true;
}

bool LockstepClock::stepOnce(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  response.success = paused_ && started_;
  if (!response.success) {
    response.message = started_ ? "not paused: call lockstep/pause first" : "time has not started";
    return true;
  }
  ++single_steps_;
  schedule();
  std::ostringstream message;
  message << "one step of " << settings_.step << " s after " << now_ << " s";
  response.message = message.str();
  return true;
}

void LockstepClock::finish() {
  finished_ = true;
  constexpr double kDrainTime = 1.0;  // [s] of wall time for observers to take the last messages
  finish_timer_ = ros::NodeHandle().createWallTimer(
      ros::WallDuration(kDrainTime), [](const ros::WallTimerEvent&) { ros::shutdown(); }, true);
}

double LockstepClock::realTimeFactor() const {
  const double wall = (ros::WallTime::now() - first_step_wall_).toSec();
  if (first_step_.isZero() || !(wall > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return (now_ - first_step_).toSec() / wall;
}

void LockstepClock::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  PlantClock::report(status);
  using diagnostic_msgs::DiagnosticStatus;
  std::vector<std::string> members, absent;
  for (const ParticipantRecord& participant : sequencer_.participants())
    (participant.joined ? members : absent).push_back(participant.name);
  status.add("lock-step participants", joined(members));
  status.add("lock-step participants absent", joined(absent));
  status.add("lock-step paused", paused_);
  status.add("forged acknowledgements", forged_);
  status.add("unexpected acknowledgements", unexpected_);
  if (const std::string* awaited = sequencer_.awaited()) status.add("awaiting", *awaited);
  for (const ParticipantRecord& participant : sequencer_.participants())
    status.add(participant.name + " drops", participant.drops);
  if (!dropped_.empty())
    status.mergeSummary(DiagnosticStatus::ERROR, "lock-step participant silent, dropped: " + joined(dropped_));
  else if (started_ && !absent.empty())
    status.mergeSummary(DiagnosticStatus::WARN, "lock-step participant absent: " + joined(absent));
  dropped_.clear();
}

}  // namespace spherical_robots
