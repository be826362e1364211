#include "spherical_robots/core/validation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spherical_robots {
namespace {

[[noreturn]] void reject(double value, std::string_view what, const char* requirement) {
  std::ostringstream message;
  message << what << " must be " << requirement << ", got " << value;
  throw std::invalid_argument(message.str());
}

}  // namespace

void requireFinite(double value, std::string_view what) {
  if (!std::isfinite(value)) reject(value, what, "finite");
}

void requirePositive(double value, std::string_view what) {
  if (!std::isfinite(value) || value <= 0.0) reject(value, what, "finite and > 0");
}

}  // namespace spherical_robots
