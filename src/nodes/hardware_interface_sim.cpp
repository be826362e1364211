// The simulated actuators behind the hardware seam (docs/hardware_interface.md).
#include "spherical_robots/ros/hardware_interface_sim_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::HardwareInterfaceSimRos>(argc, argv,
                                                                               "hardware_interface_sim");
}
