// The simulated friction drive: measured roller motor rates to the sphere's motion, with slip.
#include "spherical_robots/ros/friction_drive_sim_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::FrictionDriveSimRos>(argc, argv,
                                                                         "friction_drive_sim");
}
