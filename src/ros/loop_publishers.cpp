#include "spherical_robots/ros/loop_publishers.hpp"

#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <utility>

namespace spherical_robots {

LoopPublisher::LoopPublisher(ros::Publisher publisher,
                             std::shared_ptr<std::vector<std::string>> published)
    : publisher_(std::move(publisher)), published_(std::move(published)) {}

namespace {

void noteOnce(std::vector<std::string>& published, const std::string& topic) {
  if (std::find(published.begin(), published.end(), topic) == published.end())
    published.push_back(topic);
}

}  // namespace

void LoopPublisher::note() const { noteOnce(*published_, publisher_.getTopic()); }

void StepPublications::note(const std::string& topic) { noteOnce(*published_, topic); }

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
