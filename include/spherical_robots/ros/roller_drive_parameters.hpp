#pragma once
// What the roller stack's two friction-drive nodes share: the drive built from the stack's
// roller/ parameters (config/roller.yaml) and the URDF's sphere, and its geometry on /diagnostics.

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "spherical_robots/roller/roller_actuation.hpp"

namespace spherical_robots {

/// The roller motors' actuator names (config::kRollerActuatorNames).
const std::vector<std::string>& rollerMotorNames();

/// @throw std::invalid_argument naming a bad roller/ parameter, the URDF or the drive geometry.
roller::RollerActuation loadRollerActuation(const ros::NodeHandle& nh);

void describeRollerDrive(const roller::RollerActuation& actuation,
                         diagnostic_updater::DiagnosticStatusWrapper& status);

}  // namespace spherical_robots
