#include "spherical_robots/config/parameter_source.hpp"

#include <cmath>
#include <iostream>
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

/// Whether key holds anything, even a malformed value (which the caller's check will name).
bool isSet(const ParameterSource& source, const std::string& key) {
  try {
    return source.number(key).has_value();
  } catch (const std::invalid_argument&) {
    return true;
  }
}

}  // namespace

void ParameterSource::warn(const std::string& message) const {
  std::cerr << "warning: " << message << std::endl;
}

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

double renamedNumber(const ParameterSource& source, const RenamedKey& name, double fallback,
                     double (*check)(const ParameterSource&, const std::string&, double)) {
  if (!isSet(source, name.old_key)) return check(source, name.key, fallback);
  const bool both = isSet(source, name.key);
  const double value = check(source, both ? name.key : name.old_key, fallback);
  std::ostringstream message;
  message << source.origin() << ": parameter '" << name.old_key << "' is deprecated, renamed '"
          << name.key << "' (docs/migration.md); ";
  if (both)
    message << "both are set: using " << name.key << " = " << value << ", ignoring "
            << name.old_key;
  else
    message << "using its value as " << name.key << " = " << value;
  message << ". Rename it: the old name goes in the next release.";
  source.warn(message.str());
  return value;
}

}  // namespace spherical_robots::config
