#include "spherical_robots/config/parameter_source.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spherical_robots::config {

double finiteNumber(const ParameterSource& source, const std::string& key, double fallback) {
  const std::optional<double> value = source.number(key);
  if (!value) return fallback;
  if (!std::isfinite(*value)) {
    std::ostringstream message;
    message << source.origin() << ": parameter '" << key << "' must be finite, got " << *value;
    throw std::invalid_argument(message.str());
  }
  return *value;
}

}  // namespace spherical_robots::config
