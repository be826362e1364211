#include "spherical_robots/ros/odometry_publisher.hpp"

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>

#include <utility>

#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/plant_clock.hpp"

namespace spherical_robots {

OdometryPublisher::OdometryPublisher(PlantLoop& loop, const config::OdometryParameters& parameters,
                                     std::string odom_frame, std::string base_frame)
    : parameters_(parameters),
      odom_frame_(std::move(odom_frame)),
      base_frame_(std::move(base_frame)),
      sensors_(parameters.noise),
      odom_pub_(loop.advertise<nav_msgs::Odometry>("odom")) {
  if (parameters_.imu_rate > 0.0) {
    imu_pub_ = loop.advertise<sensor_msgs::Imu>("imu");
    imu_schedule_.emplace(1.0 / parameters_.imu_rate);
  }
}

void OdometryPublisher::publish(const ros::Time& now, const BodyMotion& truth) {
  odom_pub_.publish(
      conversions::bodyOdometry(sensors_.odometry(truth), parameters_, odom_frame_, base_frame_, now));
}

bool OdometryPublisher::imuDue(const ros::Time& now) {
  return imu_schedule_ && imu_schedule_->take(nanosecondsOf(now));
}

void OdometryPublisher::publishImu(const ros::Time& now, const BodyMotion& truth) {
  imu_pub_.publish(conversions::toImu(sensors_.imu(now.toSec(), truth), parameters_, base_frame_, now));
}

}  // namespace spherical_robots
