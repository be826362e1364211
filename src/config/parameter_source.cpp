#include "spherical_robots/config/parameter_source.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace spherical_robots::config {
namespace {

[[noreturn]] void rejectValue(const ParameterSource& source, const std::string& key, double value,
                              const std::string& requirement) {
  std::ostringstream message;
  message << source.origin() << ": parameter '" << key << "' must be " << requirement << ", got "
          << value;
  throw std::invalid_argument(message.str());
}

}  // namespace

double finiteNumber(const ParameterSource& source, const std::string& key, double fallback) {
  const std::optional<double> value = source.number(key);
  if (!value) return fallback;
  if (!std::isfinite(*value)) rejectValue(source, key, *value, "finite");
  return *value;
}

double positiveNumber(const ParameterSource& source, const std::string& key, double fallback) {
  const double value = finiteNumber(source, key, fallback);
  if (!(value > 0.0)) rejectValue(source, key, value, "> 0");
  return value;
}

double nonNegativeNumber(const ParameterSource& source, const std::string& key, double fallback) {
  const double value = finiteNumber(source, key, fallback);
  if (value < 0.0) rejectValue(source, key, value, ">= 0");
  return value;
}

int wholeNumber(const ParameterSource& source, const std::string& key, int fallback, int minimum) {
  const double value = finiteNumber(source, key, fallback);
  if (value < minimum || value != std::floor(value) ||
      value > static_cast<double>(std::numeric_limits<int>::max()))
    rejectValue(source, key, value, "an integer >= " + std::to_string(minimum));
  return static_cast<int>(value);
}

}  // namespace spherical_robots::config
