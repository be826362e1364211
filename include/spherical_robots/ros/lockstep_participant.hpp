#pragma once
// A node's side of lock-step simulated time (docs/lockstep.md). The stack's launch file lists
// the loop's participants in <ns>/lockstep/participants; a listed node does its periodic work
// when its plant asks for it on the node's own ~lockstep/step, not on a timer, takes the step's
// time from the request, and acknowledges on lockstep/ack once it has published (stamped with
// the step's time) everything it publishes for the step.

#include <ros/message_event.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/subscriber.h>
#include <ros/wall_timer.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "spherical_robots/LockstepStep.h"
#include "spherical_robots/core/latest_per_publisher.hpp"
#include "spherical_robots/core/lockstep_inputs.hpp"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

namespace spherical_robots {

/// Whether the node whose private handle is `pnh` is named in <ns>/lockstep/participants (nh's
/// namespace): then it takes part in lock-step time. A node's name is its private namespace, not
/// ros::this_node::getName(), which in a nodelet manager is the manager's.
/// @throw std::invalid_argument if the parameter is not a list of names.
bool isLockstepParticipant(const ros::NodeHandle& nh, const ros::NodeHandle& pnh);
/// <ns>/lockstep/participants resolved to node names, in order; empty if the parameter is unset.
std::vector<std::string> lockstepParticipants(const ros::NodeHandle& nh);

class LockstepParticipant;

/// The time a node works at: the step its lock-step participant works at, or ROS time if it takes
/// no part (nullptr).
ros::Time workingTime(const LockstepParticipant* participant);

class LockstepParticipant {
 public:
  /// What the work of one step did: the topics it published (each message stamped with the
  /// step's time) and the earliest step time it has work again (zero: the next step).
  struct Done {
    std::vector<std::string> published;
    ros::Time next;
  };
  /// The work of one step; nullopt: the step goes on elsewhere, and answer() ends it later.
  using Work = std::function<std::optional<Done>(const ros::Time& now)>;

  /// @param pnh the node's private handle: its namespace is the node's name, the participant's.
  /// @param subscriptions the topics the node reads (what a request may make it wait for).
  /// Sends join requests, once every subscription has had a publisher for a second, until the first
  /// request, and again whenever no request has come for rejoin_after [s] of wall time (so a
  /// dropped participant comes back).
  LockstepParticipant(ros::NodeHandle nh, const ros::NodeHandle& pnh,
                      std::vector<ros::Subscriber> subscriptions, Work work, double rejoin_after = 1.0);

  /// Asks to join only while ready() also holds (e.g. a controller that has something to follow),
  /// so that time starts with the node able to work.
  void joinOnlyWhen(std::function<bool()> ready) { ready_ = std::move(ready); }
  /// A message stamped `stamp` arrived on `topic` from `publisher` (the message event's
  /// getPublisherName()); call from the subscription's callback, after the node took the message
  /// in or rejected it.
  void received(const std::string& topic, const ros::Time& stamp, const std::string& publisher);
  /// The same from the subscription's message event: its message's header stamp and publisher.
  template <typename Message>
  void received(const std::string& topic, const ros::MessageEvent<Message const>& event) {
    received(topic, event.getConstMessage()->header.stamp, event.getPublisherName());
  }
  /// While the step works: the publisher whose message on `topic` it waited for (empty: any),
  /// nullopt if its request did not list the topic (LockstepInputs::expectedPublisher).
  std::optional<std::string> expectedPublisher(const std::string& topic) const {
    return inputs_.expectedPublisher(topic);
  }
  /// Acknowledges the step whose work returned nullopt.
  void answer(const Done& done);
  /// The time of the latest step worked at (zero before the first).
  const ros::Time& now() const { return now_; }
  unsigned long steps() const { return steps_; }
  /// The CPU the latest request named and this process's threads were moved to (-1: none).
  int cpu() const { return cpu_; }

 private:
  void onRequest(const spherical_robots::LockstepStep& request);
  void workIfReady();
  void sendJoin(const ros::WallTimerEvent&);

  std::string name_;
  std::vector<ros::Subscriber> subscriptions_;
  LockstepInputs inputs_;
  Work work_;
  std::function<bool()> ready_;
  double rejoin_after_;
  std::optional<ros::Time> pending_;
  ros::Time now_;
  ros::WallTime last_request_wall_;
  ros::WallTime connected_since_;  ///< since when every subscription has a publisher
  unsigned long steps_ = 0;
  int cpu_ = -1;
  ros::Publisher ack_pub_;
  ros::Subscriber request_sub_;
  ros::WallTimer join_timer_;
};

/// A node that answers each message of one input at once (a relay, a message-driven
/// controller), in either time: outside lock-step it handles a message when it arrives; as a
/// listed participant it handles, at each step, the message stamped with the step's time from the
/// publisher the request names, if one came (whatever order the transport delivered it in; a
/// stray node's message stamped alike is not the loop's), and acknowledges what that published.
template <typename Message>
class MessageDrivenWork {
 public:
  /// Handles one message, publishing through LoopPublishers of `publications`.
  using Handle = std::function<void(const Message&)>;

  MessageDrivenWork(Handle handle, StepPublications& publications)
      : handle_(std::move(handle)), publications_(&publications) {}

  /// Takes part in lock-step if the node (private handle pnh) is listed (call once the
  /// subscriptions exist; the first is the input).
  void join(ros::NodeHandle nh, const ros::NodeHandle& pnh,
            std::vector<ros::Subscriber> subscriptions) {
    if (!isLockstepParticipant(nh, pnh)) return;
    topic_ = subscriptions.front().getTopic();
    participant_ = std::make_unique<LockstepParticipant>(
        nh, pnh, std::move(subscriptions), [this](const ros::Time& now) {
          LockstepParticipant::Done done;
          const std::optional<std::string> publisher = participant_->expectedPublisher(topic_);
          if (const Message* input = publisher ? latest_.at(nanosecondsOf(now), *publisher) : nullptr) {
            handle_(*input);
            done.published = publications_->take();
          }
          return done;
        });
  }
  /// From the input's callback.
  void arrived(const ros::MessageEvent<Message const>& event) {
    const Message& message = *event.getConstMessage();
    if (!participant_) {
      handle_(message);
      publications_->take();
      return;
    }
    latest_.keep(event.getPublisherName(), nanosecondsOf(message.header.stamp), message);
    participant_->received(topic_, event);
  }
  /// Null outside lock-step (another input's callback reports its messages to it).
  LockstepParticipant* participant() const { return participant_.get(); }

 private:
  Handle handle_;
  StepPublications* publications_;
  std::string topic_;  ///< the input's resolved name (in lock-step)
  LatestPerPublisher<Message> latest_;
  std::unique_ptr<LockstepParticipant> participant_;
};

}  // namespace spherical_robots
