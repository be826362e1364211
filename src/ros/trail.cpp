#include "spherical_robots/ros/trail.hpp"

#include <stdexcept>
#include <utility>

#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/plant_clock.hpp"

namespace spherical_robots {

Trail::Trail(ros::NodeHandle& nh, const std::string& topic, std::string frame_id, double period,
             std::size_t max_poses, bool latch)
    : frame_id_(std::move(frame_id)), period_(period), max_poses_(max_poses) {
  if (!(period > 0.0) || max_poses == 0) {
    throw std::invalid_argument("trail " + nh.resolveName(topic) + ": period " +
                                std::to_string(period) + " s and pose limit " +
                                std::to_string(max_poses) + " must be > 0");
  }
  publisher_ = nh.advertise<nav_msgs::Path>(topic, 1, latch);
  path_.header.frame_id = frame_id_;
}

bool Trail::due(const ros::Time& now) const { return periodDue(last_, now, period_); }

void Trail::add(const ros::Time& now, const Eigen::Vector3d& position,
                const Eigen::Quaterniond& orientation) {
  last_ = now;
  path_.header.stamp = now;
  path_.poses.push_back(conversions::toPoseStamped(position, orientation, frame_id_, now));
  if (path_.poses.size() > max_poses_) path_.poses.erase(path_.poses.begin());
  publish();
}

void Trail::clear() {
  path_.poses.clear();
  last_ = ros::Time();
}

void Trail::publish() const { publisher_.publish(path_); }

}  // namespace spherical_robots
