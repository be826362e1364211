#pragma once
// Publications of the simulated loop. Deep enough for observers: in lock-step the stack runs as
// fast as its participants answer, and an observer (a bag recorder, rviz) is not one, so when it
// is descheduled the messages wait in the publisher's queue for it instead of being dropped. And
// counted: what a node published in a step is what lock-step tells the next participant to wait
// for (docs/lockstep.md), so each publication notes its topic instead of a hand-kept list.

#include <geometry_msgs/TransformStamped.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "spherical_robots/ros/shared_message.hpp"

namespace spherical_robots {

/// Messages a publisher of the loop holds for a subscriber that falls behind (a few seconds of
/// the fastest topic, 1 kHz, at a few times real time), and a participant's subscription to a
/// loop input holds: a burst of foreign messages on the topic (a flood of bad terrain_state, 100
/// in 0.2 s of wall time in hostile_input_roller) must not push the step's own message out of a
/// short queue, or the participant waits for it in vain and the robot stops.
constexpr std::uint32_t kLoopQueueSize = 5000;

/// A publisher of a loop topic: each publish() notes the topic in its StepPublications.
class LoopPublisher {
 public:
  LoopPublisher() = default;
  LoopPublisher(ros::Publisher publisher, std::shared_ptr<std::vector<std::string>> published);

  /// By shared pointer (shared_message.hpp): a nodelet in the same manager receives the message
  /// itself, neither serialised nor copied.
  template <typename Message>
  void publish(Message&& message) const {
    publisher_.publish(shared(std::forward<Message>(message)));
    note();
  }
  /// The resolved topic.
  std::string topic() const { return publisher_.getTopic(); }
  const ros::Publisher& publisher() const { return publisher_; }

 private:
  void note() const;

  ros::Publisher publisher_;
  std::shared_ptr<std::vector<std::string>> published_;
};

/// The loop topics one node published since the last take(), each once.
class StepPublications {
 public:
  /// Advertises `topic` (relative to nh) with kLoopQueueSize.
  template <typename Message>
  LoopPublisher advertise(ros::NodeHandle& nh, const std::string& topic) {
    return {nh.advertise<Message>(topic, kLoopQueueSize), published_};
  }
  /// A publication on resolved `topic` made by other means in this step (an actionlib server's
  /// result), so that it is listed with the ones of advertise()'s publishers.
  void note(const std::string& topic);
  /// The resolved topics published since the last call, in order of first publication.
  std::vector<std::string> take();

 private:
  std::shared_ptr<std::vector<std::string>> published_ =
      std::make_shared<std::vector<std::string>>();
};

/// tf2_ros::TransformBroadcaster on a LoopPublisher of /tf (kLoopQueueSize instead of its 100).
class TfPublisher {
 public:
  explicit TfPublisher(StepPublications& step);
  void sendTransform(const geometry_msgs::TransformStamped& transform) const;
  void sendTransform(const std::vector<geometry_msgs::TransformStamped>& transforms) const;

 private:
  LoopPublisher publisher_;
};

}  // namespace spherical_robots
