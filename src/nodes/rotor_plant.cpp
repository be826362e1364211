// The two-rotor sphere rolled from its measured rotor speeds (Svinin et al., eqs 6-11).
#include "spherical_robots/ros/rotor_plant_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::RotorPlantRos>(argc, argv,
                                                                    "rotor_plant");
}
