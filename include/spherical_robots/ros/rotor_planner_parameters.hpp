#pragma once
// Every parameter of the rotor_planner node, loaded and checked in one place (docs/nodes.md,
// "rotor_planner", has the table: name, default, meaning).

#include <optional>
#include <string>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/rotor/manoeuvre_executive.hpp"

namespace spherical_robots {

struct RotorPlannerParameters {
  /// ~manoeuvre: a plan request made at start-up and executed from the first command period.
  struct StartUpManoeuvre {
    double k = 2.5;
    int steps = 2;
    double u = 0.0;    ///< [m]
    double v = 0.0;    ///< [m]
    double psi = 0.0;  ///< [rad]
    int index = 0;     ///< the solution executed
  };

  double max_radius = 0.07;        ///< [m] a request's default limit of the circle radii
  double max_position = 1e3;       ///< [m] an odom position beyond it is rejected
  double max_stamp_skew = 1.0;     ///< [s] an odom stamped further from the clock is rejected
  std::string frame_id = "odom";   ///< the plane frame of planned_path and driven_path
  std::string sphere_frame = "base_link";  ///< the frame of the contact_curve marker
  int samples_per_step = 200;      ///< poses of planned_path per figure eight
  double path_period = 0.05;       ///< [s] between poses of driven_path
  double odom_timeout = 0.5;       ///< [s] an older odom is stale
  std::optional<double> robot_inertia_ratio;  ///< inertia_ratio of the robot, if set
  std::optional<StartUpManoeuvre> manoeuvre;
  rotor::ManoeuvreExecutive::Parameters executive;  ///< radius: ~sphere_radius
};

/// stack: the stack's namespace (the robot's rotor_inertia_scale, inertia_ratio); node: the
/// private one. @throw std::invalid_argument naming the parameter, its value and its limit.
RotorPlannerParameters loadRotorPlannerParameters(const config::ParameterSource& stack,
                                                  const config::ParameterSource& node);

}  // namespace spherical_robots
