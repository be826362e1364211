// The two-rotor sphere's geometric-phase motion planner as a service (Svinin et al.).
#include "spherical_robots/ros/rotor_planner_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::RotorPlannerRos>(argc, argv, "rotor_planner");
}
