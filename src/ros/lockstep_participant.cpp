#include "spherical_robots/ros/lockstep_participant.hpp"

#include <ros/console.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "spherical_robots/LockstepAck.h"
#include "spherical_robots/core/loop_cpu.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/ros/shared_message.hpp"

namespace spherical_robots {
namespace {

const char* const kParticipantsParam = "lockstep/participants";

std::vector<std::string> topicsOf(const std::vector<ros::Subscriber>& subscriptions) {
  std::vector<std::string> topics;
  for (const ros::Subscriber& subscription : subscriptions) topics.push_back(subscription.getTopic());
  return topics;
}

}  // namespace

std::vector<std::string> lockstepParticipants(const ros::NodeHandle& nh) {
  std::vector<std::string> names;
  // A list of node names, e.g. [pure_pursuit_controller, hardware_interface]; texts() names the
  // parameter and the value that is not one.
  for (const std::string& name : RosParameterSource(nh).texts(kParticipantsParam).value_or(std::vector<std::string>{}))
    names.push_back(nh.resolveName(name));
  return names;
}

ros::Time workingTime(const LockstepParticipant* participant) {
  return participant ? participant->now() : ros::Time::now();
}

bool isLockstepParticipant(const ros::NodeHandle& nh, const ros::NodeHandle& pnh) {
  const std::vector<std::string> names = lockstepParticipants(nh);
  return std::find(names.begin(), names.end(), pnh.getNamespace()) != names.end();
}

LockstepParticipant::LockstepParticipant(ros::NodeHandle nh, const ros::NodeHandle& pnh,
                                         std::vector<ros::Subscriber> subscriptions, Work work,
                                         double rejoin_after)
    : name_(pnh.getNamespace()), subscriptions_(std::move(subscriptions)),
      inputs_(topicsOf(subscriptions_)), work_(std::move(work)), rejoin_after_(rejoin_after) {
  // Queues long enough that no request or acknowledgement is lost while a node is descheduled.
  ack_pub_ = nh.advertise<spherical_robots::LockstepAck>("lockstep/ack", 100);
  // Its own requests only (docs/lockstep.md): the plant publishes each participant's on that
  // participant's ~lockstep/step.
  request_sub_ = ros::NodeHandle(pnh, "lockstep").subscribe("step", 100, &LockstepParticipant::onRequest,
                                                            this, ros::TransportHints().tcpNoDelay());
  join_timer_ = nh.createWallTimer(ros::WallDuration(0.25), &LockstepParticipant::sendJoin, this);
  ROS_INFO_STREAM(name_ << " takes part in lock-step time (" << request_sub_.getTopic() << ")");
}

void LockstepParticipant::sendJoin(const ros::WallTimerEvent&) {
  if (!last_request_wall_.isZero() &&
      (ros::WallTime::now() - last_request_wall_).toSec() < rejoin_after_)
    return;
  if (ready_ && !ready_()) return;
  // Joined before its inputs are connected, it would wait for messages that were never sent.
  // A subscriber sees a publisher before that publisher has finished its side of the
  // connection and sends to it, so it waits a second more.
  constexpr double kSettleTime = 1.0;  // [s] of wall time
  for (const ros::Subscriber& subscription : subscriptions_) {
    if (subscription.getNumPublishers() == 0) {
      connected_since_ = ros::WallTime();
      return;
    }
  }
  if (connected_since_.isZero()) connected_since_ = ros::WallTime::now();
  if ((ros::WallTime::now() - connected_since_).toSec() < kSettleTime) return;
  spherical_robots::LockstepAck join;
  join.participant = name_;
  ack_pub_.publish(join);
}

void LockstepParticipant::received(const std::string& topic, const ros::Time& stamp,
                                   const std::string& publisher) {
  inputs_.received(topic, nanosecondsOf(stamp), publisher);
  if (pending_) workIfReady();
}

void LockstepParticipant::onRequest(const spherical_robots::LockstepStep& request) {
  if (request.participant != name_) return;
  last_request_wall_ = ros::WallTime::now();
  if (request.cpu >= 0 && request.cpu != cpu_) {
    // Once per CPU named: in a nodelet manager the plant has moved the process already.
    const std::string failure = pinProcessToCpu(request.cpu);
    if (failure.empty())
      ROS_INFO_STREAM(name_ << " runs on CPU " << request.cpu << ", the lock-step loop's");
    else
      ROS_WARN_STREAM(name_ << " stays where it is: moving to the lock-step loop's CPU failed: " << failure);
    cpu_ = request.cpu;
  }
  std::vector<PublishedTopic> inputs;
  const bool publishers_named = request.input_publishers.size() == request.inputs.size();
  for (std::size_t i = 0; i < request.inputs.size() && i < request.input_stamps.size(); ++i)
    inputs.push_back({request.inputs[i], nanosecondsOf(request.input_stamps[i]),
                      publishers_named ? request.input_publishers[i] : std::string()});
  if (pending_)
    ROS_WARN_STREAM("lock-step: a request for " << request.stamp << " s replaces the one for "
                                                << *pending_ << " s, whose inputs never came");
  inputs_.expect(inputs);
  pending_ = request.stamp;
  workIfReady();
}

void LockstepParticipant::workIfReady() {
  if (!inputs_.satisfied()) return;
  now_ = *pending_;
  pending_.reset();
  if (const std::optional<Done> done = work_(now_)) answer(*done);
}

void LockstepParticipant::answer(const Done& done) {
  ++steps_;
  spherical_robots::LockstepAck ack;
  ack.stamp = now_;
  ack.participant = name_;
  ack.published = done.published;
  ack.next = done.next;
  ack_pub_.publish(shared(std::move(ack)));
}

}  // namespace spherical_robots
