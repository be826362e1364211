#include "spherical_robots/ros/loop_publishers.hpp"

#include <tf2_msgs/TFMessage.h>

namespace spherical_robots {

TfPublisher::TfPublisher()
    : publisher_(ros::NodeHandle().advertise<tf2_msgs::TFMessage>("/tf", kLoopQueueSize)) {}

void TfPublisher::sendTransform(const geometry_msgs::TransformStamped& transform) {
  sendTransform(std::vector<geometry_msgs::TransformStamped>{transform});
}

void TfPublisher::sendTransform(const std::vector<geometry_msgs::TransformStamped>& transforms) {
  tf2_msgs::TFMessage message;
  message.transforms = transforms;
  publisher_.publish(message);
}

}  // namespace spherical_robots
