#pragma once
// Input checks shared by every core function: a bad number is rejected where it enters, with a
// message naming it, instead of travelling on as a NaN.

#include <cmath>
#include <string_view>

namespace spherical_robots {

/// @throw std::invalid_argument "<what> must be <requirement>, got <value>". Out of line, so that
/// the checks below inline as a compare or two: the ODE right-hand sides make them millions of
/// times per run.
[[noreturn]] void rejectNumber(double value, std::string_view what, const char* requirement);
[[noreturn]] void rejectMagnitude(double value, double bound, std::string_view what);

/// @throw std::invalid_argument "<what> must be finite, got <value>" unless value is finite.
inline void requireFinite(double value, std::string_view what) {
  if (!std::isfinite(value)) rejectNumber(value, what, "finite");
}

/// @throw std::invalid_argument "<what> must be finite and > 0, got <value>" unless it is.
inline void requirePositive(double value, std::string_view what) {
  if (!std::isfinite(value) || value <= 0.0) rejectNumber(value, what, "finite and > 0");
}

/// Plausibility, not only finiteness: a number far outside its physical range (1e300 m/s) is as
/// wrong as a NaN and overflows into one two operations later.
/// @throw std::invalid_argument "<what> must be finite with magnitude <= <bound>, got <value>".
inline void requireMagnitudeAtMost(double value, double bound, std::string_view what) {
  if (!(std::abs(value) <= bound)) rejectMagnitude(value, bound, what);
}

}  // namespace spherical_robots
