#include "spherical_robots/ros/loop_publishers.hpp"

#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <utility>

namespace spherical_robots {

LoopPublisher::LoopPublisher(ros::Publisher publisher,
                             std::shared_ptr<std::vector<std::string>> published)
    : publisher_(std::move(publisher)), published_(std::move(published)) {}

void LoopPublisher::note() const {
  const std::string topic = publisher_.getTopic();
  if (std::find(published_->begin(), published_->end(), topic) == published_->end())
    published_->push_back(topic);
}

std::vector<std::string> StepPublications::take() {
  std::vector<std::string> topics;
  topics.swap(*published_);
  return topics;
}

TfPublisher::TfPublisher(StepPublications& step) {
  ros::NodeHandle root;
  publisher_ = step.advertise<tf2_msgs::TFMessage>(root, "/tf");
}

void TfPublisher::sendTransform(const geometry_msgs::TransformStamped& transform) const {
  sendTransform(std::vector<geometry_msgs::TransformStamped>{transform});
}

void TfPublisher::sendTransform(const std::vector<geometry_msgs::TransformStamped>& transforms) const {
  tf2_msgs::TFMessage message;
  message.transforms = transforms;
  publisher_.publish(message);
}

}  // namespace spherical_robots
