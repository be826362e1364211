#pragma once
// The Norma stack's model and controller parameters that are not geometry (config/norma.yaml;
// urdf/norma.urdf holds the masses and lengths): one reader for norma_plant, norma_controller
// and `sphere_sim norma`. The nodes read their private namespace (prefix ""); sphere_sim reads
// config/norma.yaml with the prefixes kNormaPlantKeys and kNormaControllerKeys, the same keys
// the launch file loads into the stack's namespace.

#include <string>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/norma/norma_control_loop.hpp"
#include "spherical_robots/norma/norma_controller.hpp"
#include "spherical_robots/norma/norma_dynamics.hpp"

namespace spherical_robots::config {

/// norma_plant's block of config/norma.yaml.
inline const std::string kNormaPlantKeys = "norma_plant/";
/// norma_controller's block of config/norma.yaml.
inline const std::string kNormaControllerKeys = "norma_controller/";

/// The plant's model: which Lagrangian and where the heading starts.
struct NormaModelParameters {
  norma::LagrangianVariant variant = norma::LagrangianVariant::kText;  ///< docs/errata.md
  double initial_psi = 0.0;  ///< [rad]; the stack's (config/norma.yaml) is pathStartHeading()
};

/// The controller, its gains and the actuators' effort limits it winds up against.
struct NormaControlParameters {
  norma::ControllerKind controller = norma::ControllerKind::kPaper;
  norma::ControllerGains gains;  ///< of both controllers (section 5's and this project's)
  norma::EffortLimits limits;    ///< max_torque [N m], max_force [N], > 0
};

/// Keys prefix + variant (text | appendix), prefix + initial_psi (finite); absent: `fallback`'s.
/// @throw std::invalid_argument naming the key, its value and the source on a bad value.
NormaModelParameters normaModelParameters(const ParameterSource& source,
                                          const std::string& prefix = "",
                                          const NormaModelParameters& fallback = {});

/// Keys prefix + controller (paper | tracking), prefix + max_torque, prefix + max_force (> 0),
/// prefix + gains/kinematic/{k1, k2, k3}, prefix + gains/{rate, pendulum, slider,
/// tracking_slider}/{kp, ki, kd}, prefix + gains/{along_gain, cross_gain, heading_gain,
/// tilt_gain, tilt_damping, max_slider} (norma::ControllerGains, checked by norma::validate);
/// absent: `fallback`'s.
/// @throw std::invalid_argument naming the key, its value and the source on a bad value.
NormaControlParameters normaControlParameters(const ParameterSource& source,
                                              const std::string& prefix = "",
                                              const NormaControlParameters& fallback = {});

}  // namespace spherical_robots::config
