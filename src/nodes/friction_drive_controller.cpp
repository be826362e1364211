// The friction drive's inverse kinematics between the controller and the roller motors.
#include "spherical_robots/ros/friction_drive_controller_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::FrictionDriveControllerRos>(
      argc, argv, "friction_drive_controller");
}
