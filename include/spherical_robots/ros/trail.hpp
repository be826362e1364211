#pragma once
// Where something has been, for rviz: the driven trails of the terrain, roller and Norma plants,
// the FreeBOT end-effector's trail and the rotor sphere's driven path.

#include <nav_msgs/Path.h>
#include <ros/ros.h>

#include <Eigen/Geometry>
#include <cstddef>
#include <string>

namespace spherical_robots {

/// A nav_msgs/Path in frame_id on `topic` that gains a pose once `period` [s] of ROS time has
/// passed since the last one (or time went back), drops its oldest pose past max_poses, and is
/// published at each gain.
class Trail {
 public:
  /// @throw std::invalid_argument unless period > 0 and max_poses > 0.
  Trail(ros::NodeHandle& nh, const std::string& topic, std::string frame_id, double period,
        std::size_t max_poses, bool latch = false);

  /// The period has passed since the last pose (or time went back, or there is none).
  bool due(const ros::Time& now) const;
  /// Adds the pose stamped `now` and publishes; call it when due().
  void add(const ros::Time& now, const Eigen::Vector3d& position,
           const Eigen::Quaterniond& orientation);
  /// Starts over (a new run), publishing nothing until the next add().
  void clear();
  void publish() const;

 private:
  ros::Publisher publisher_;
  std::string frame_id_;
  double period_;
  std::size_t max_poses_;
  nav_msgs::Path path_;
  ros::Time last_;
};

}  // namespace spherical_robots
