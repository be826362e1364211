#include "spherical_robots/core/validation.hpp"

#include <sstream>
#include <stdexcept>

namespace spherical_robots {

void rejectNumber(double value, std::string_view what, const char* requirement) {
  std::ostringstream message;
  message << what << " must be " << requirement << ", got " << value;
  throw std::invalid_argument(message.str());
}

void rejectMagnitude(double value, double bound, std::string_view what) {
  std::ostringstream message;
  message << what << " must be finite with magnitude <= " << bound << ", got " << value;
  throw std::invalid_argument(message.str());
}

void requireAtLeast(double value, double minimum, std::string_view what) {
  if (std::isfinite(value) && value >= minimum) return;
  std::ostringstream message;
  message << what << " must be finite and >= " << minimum << ", got " << value;
  throw std::invalid_argument(message.str());
}

}  // namespace spherical_robots
