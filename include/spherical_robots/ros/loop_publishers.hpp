#pragma once
// Publications of the simulated loop deep enough for observers: in lock-step the stack runs as
// fast as its participants answer, and an observer (a bag recorder, rviz) is not one, so when it
// is descheduled the messages wait in the publisher's queue for it instead of being dropped.

#include <geometry_msgs/TransformStamped.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <cstdint>
#include <vector>

namespace spherical_robots {

/// Messages a publisher of the loop holds for a subscriber that falls behind (a few seconds of
/// the fastest topic, 1 kHz, at a few times real time).
constexpr std::uint32_t kLoopQueueSize = 5000;

/// tf2_ros::TransformBroadcaster with kLoopQueueSize instead of its 100 on /tf.
class TfPublisher {
 public:
  TfPublisher();
  void sendTransform(const geometry_msgs::TransformStamped& transform);
  void sendTransform(const std::vector<geometry_msgs::TransformStamped>& transforms);

 private:
  ros::Publisher publisher_;
};

}  // namespace spherical_robots
