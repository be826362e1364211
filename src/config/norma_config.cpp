#include "spherical_robots/config/norma_config.hpp"

namespace spherical_robots::config {

NormaModelParameters normaModelParameters(const ParameterSource& source, const std::string& prefix,
                                          const NormaModelParameters& fallback) {
  NormaModelParameters p;
  p.variant = parsedText(source, prefix + "variant", norma::toString(fallback.variant),
                         norma::lagrangianVariantFromString);
  p.initial_psi = finiteNumber(source, prefix + "initial_psi", fallback.initial_psi);
  return p;
}

NormaControlParameters normaControlParameters(const ParameterSource& source,
                                              const std::string& prefix,
                                              const NormaControlParameters& fallback) {
  NormaControlParameters p;
  p.controller = parsedText(source, prefix + "controller", norma::toString(fallback.controller),
                            norma::controllerKindFromString);
  p.limits.max_torque = positiveNumber(source, prefix + "max_torque", fallback.limits.max_torque);
  p.limits.max_force = positiveNumber(source, prefix + "max_force", fallback.limits.max_force);
  return p;
}

}  // namespace spherical_robots::config
