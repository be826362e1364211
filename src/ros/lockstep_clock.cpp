#include "spherical_robots/ros/lockstep_clock.hpp"

#include <boost/algorithm/string/join.hpp>
#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/callback_queue.h>
#include <ros/console.h>
#include <ros/init.h>
#include <ros/this_node.h>
#include <rosgraph_msgs/Clock.h>

#include <stdexcept>
#include <utility>

#include "spherical_robots/LockstepStep.h"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/queued_call.hpp"

namespace spherical_robots {
namespace {

std::string joined(const std::vector<std::string>& names) {
  return names.empty() ? "none" : boost::algorithm::join(names, ", ");
}

}  // namespace

LockstepClock::LockstepClock(ros::NodeHandle nh, Settings settings, Tick tick, Ready ready)
    : settings_(std::move(settings)), tick_(std::move(tick)), ready_(std::move(ready)),
      sequencer_(ros::this_node::getName(), settings_.participants, settings_.timeout),
      inputs_(settings_.subscriptions), pace_(settings_.step, settings_.speedup),
      clock_publication_(settings_.clock_rate), queue_(nh.getCallbackQueue()),
      created_wall_(ros::WallTime::now()), nh_(nh) {
  if (settings_.loop_cpu.kind == LoopCpuSetting::Kind::kAuto)
    cpu_ticks_at_creation_ = readCpuTicks();
  else  // a fixed CPU checked now, so that a bad one stops the plant before time starts
    loopCpuFor(settings_.loop_cpu, allowedCpus(), {}, {});
  if (!ros::Time::isSimTime())
    throw std::invalid_argument("lock-step clock publishes /clock, but /use_sim_time is not true, "
                                "so no node would follow it");
  if (!queue_) queue_ = ros::getGlobalCallbackQueue();
  const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
  // Each participant's requests on a topic of its own, so that a request wakes only the node it
  // names: advertised now for the listed ones, so that they are connected when they ask to join.
  for (const std::string& participant : settings_.participants) requestPublisher(participant);
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
  ROS_INFO_STREAM("Lock-step " << (settings_.leader.empty() ? "/clock: " + pace_.describe()
                                                          : "time of " + settings_.leader + ", as it asks")
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
    } else if (requestPublisher(ack.participant).getNumSubscribers() == 0) {
      // Not yet connected to its request topic: it asks again every 0.25 s.
      ROS_INFO_STREAM_THROTTLE(1.0, "lock-step: " << ack.participant << " asks to join; waiting for "
                                                  << "it to subscribe to its requests");
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
      placeLoop();
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
  // A step still waiting for an answer after a poll period: its time is sent (no-op if it was).
  if (sequencer_.stepInProgress()) publishClock(true);
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

void LockstepClock::placeLoop() {
  const std::vector<int> allowed = allowedCpus();
  loop_cpu_ = loopCpuFor(settings_.loop_cpu, allowed, cpu_ticks_at_creation_, readCpuTicks());
  if (loop_cpu_ < 0) return;
  if (const std::string failure = pinProcessToCpu(loop_cpu_); !failure.empty()) {
    ROS_WARN_STREAM("lock-step: the loop stays spread over the CPUs: " << failure);
    loop_cpu_ = -1;
    return;
  }
  ROS_INFO_STREAM("lock-step: the loop runs on CPU " << loop_cpu_ << " of " << allowed.size()
                  << " (loop_cpu " << settings_.loop_cpu.toString() << ")");
}

void LockstepClock::schedule() {
  if (finished_ || scheduled_ || sequencer_.stepInProgress()) return;
  const auto delay = pace_.delayBefore(nanosecondsOf(now_ + ros::Duration(settings_.step)),
                                       ros::WallTime::now().toSec());
  if (started_ && (!delay || *delay > 0.0)) publishClock(true);  // paused or paced: time waits
  if (!delay) return;
  scheduled_ = true;
  if (*delay > 0.0) {
    pace_timer_.setPeriod(ros::WallDuration(*delay));
    pace_timer_.start();
    return;
  }
  // From a callback that ended a step which waited for an answer, the next step starts at once:
  // the callbacks queued meanwhile (services, messages) are served while it waits in turn. A step
  // that waited for nothing (no participant, no input) is queued instead of called, so that steps
  // do not recurse and the queue is still served. (Queuing every step costs a nodelet manager two
  // thread hand-offs a step.)
  if (!in_run_step_) {
    runStep();
    return;
  }
  queue_->addCallback(queuedCall([this] { runStep(); }));
}

void LockstepClock::runStep() {
  scheduled_ = false;
  pace_timer_.stop();
  runStepAt(now_ + ros::Duration(settings_.step));
}

void LockstepClock::runStepAt(const ros::Time& t) {
  in_run_step_ = true;
  now_ = t;
  pace_.started(nanosecondsOf(now_), ros::WallTime::now().toSec());
  publishClock(false);
  const std::vector<std::string> published = tick_(now_);
  sequencer_.beginStep(nanosecondsOf(now_), published, ros::WallTime::now().toSec());
  pump();
  in_run_step_ = false;
}

void LockstepClock::publishClock(bool waiting) {
  const double wall = ros::WallTime::now().toSec();
  if (!settings_.leader.empty() || !clock_publication_.due(nanosecondsOf(now_), wall, waiting))
    return;
  rosgraph_msgs::Clock clock;
  clock.clock = now_;
  clock_pub_.publish(clock);
  clock_publication_.published(nanosecondsOf(now_), wall);
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
    step.stamp = timeOf(request->stamp);
    step.participant = request->participant;
    step.cpu = leader_link_ ? leader_link_->cpu() : loop_cpu_;
    for (const PublishedTopic& input : request->inputs) {
      step.inputs.push_back(input.topic);
      step.input_stamps.push_back(timeOf(input.stamp));
      step.input_publishers.push_back(input.publisher);
    }
    requestPublisher(request->participant).publish(step);
    return;
  }
}

ros::Publisher& LockstepClock::requestPublisher(const std::string& participant) {
  auto [it, inserted] = request_pubs_.try_emplace(participant);
  if (inserted)
    it->second = nh_.advertise<spherical_robots::LockstepStep>(participant + "/lockstep/step", 100);
  return it->second;
}

void LockstepClock::received(const std::string& topic, const ros::Time& stamp,
                             const std::string& publisher) {
  inputs_.received(topic, nanosecondsOf(stamp), publisher);
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
  pace_.pause();
  ROS_INFO_STREAM("lock-step: paused at " << now_ << " s");
  return true;
}

bool LockstepClock::resume(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  pace_.resume();
  ROS_INFO_STREAM("lock-step: resumed at " << now_ << " s");
  if (started_) schedule();
  return true;
}

bool LockstepClock::stepOnce(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& response) {
  const std::string refusal = started_ ? pace_.stepOnce() : "time has not started";
  response.success = refusal.empty();
  response.message = response.success ? "one step after " + std::to_string(now_.toSec()) + " s" : refusal;
  if (response.success) schedule();
  return true;
}

void LockstepClock::finish() {
  finished_ = true;
  publishClock(true);
  pace_.finished(ros::WallTime::now().toSec());
  constexpr double kDrainTime = 1.0;  // [s] of wall time for observers to take the last messages
  finish_timer_ = ros::NodeHandle().createWallTimer(
      ros::WallDuration(kDrainTime), [](const ros::WallTimerEvent&) { ros::shutdown(); }, true);
}

double LockstepClock::realTimeFactor() const {
  return pace_.realTimeFactor(nanosecondsOf(now_), ros::WallTime::now().toSec());
}

void LockstepClock::report(diagnostic_updater::DiagnosticStatusWrapper& status) {
  PlantClock::report(status);
  using diagnostic_msgs::DiagnosticStatus;
  std::vector<std::string> members, absent;
  for (const ParticipantRecord& participant : sequencer_.participants())
    (participant.joined ? members : absent).push_back(participant.name);
  status.add("lock-step participants", joined(members));
  status.add("lock-step participants absent", joined(absent));
  status.add("lock-step paused", pace_.paused());
  status.add("lock-step CPU", leader_link_ ? leader_link_->cpu() : loop_cpu_);
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
