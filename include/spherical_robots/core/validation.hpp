#pragma once
// Input checks shared by every core function: a bad number is rejected where it enters, with a
// message naming it, instead of travelling on as a NaN.

#include <cmath>
#include <initializer_list>
#include <string_view>
#include <utility>

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

/// @throw std::invalid_argument "<what> must be finite and >= 0, got <value>" unless it is.
inline void requireNonNegative(double value, std::string_view what) {
  if (!std::isfinite(value) || value < 0.0) rejectNumber(value, what, "finite and >= 0");
}

/// requirePositive on each (value, what) in order: the first that is not finite and > 0 throws.
inline void requireAllPositive(std::initializer_list<std::pair<double, std::string_view>> fields) {
  for (const auto& [value, what] : fields) requirePositive(value, what);
}

/// requireFinite on each (value, what) in order: the first that is not finite throws. Inline, as
/// the single checks: the control loops make it at every step.
inline void requireAllFinite(std::initializer_list<std::pair<double, std::string_view>> fields) {
  for (const auto& [value, what] : fields) requireFinite(value, what);
}

/// Whether every value is finite, by one test of their sum where it is finite (a NaN or an infinity
/// makes the sum NaN or infinite): the closed loop checks some 20 values at every RK stage, and a
/// test each cost it 9 % of its instructions. Each value is tested only if the sum overflowed.
template <typename... Values>
inline bool allFinite(double first, Values... rest) {
  return std::isfinite((first + ... + rest)) ||
         (std::isfinite(first) && (std::isfinite(rest) && ...));
}

/// @throw std::invalid_argument "<what> must be finite and >= <minimum>, got <value>" unless it is.
void requireAtLeast(double value, double minimum, std::string_view what);

/// Plausibility, not only finiteness: a number far outside its physical range (1e300 m/s) is as
/// wrong as a NaN and overflows into one two operations later.
/// @throw std::invalid_argument "<what> must be finite with magnitude <= <bound>, got <value>".
inline void requireMagnitudeAtMost(double value, double bound, std::string_view what) {
  if (!(std::abs(value) <= bound)) rejectMagnitude(value, bound, what);
}

/// The largest length [m] (a radius, a target, a position) and the largest speed [m/s or rad/s]
/// a model here takes: every robot of the five papers is well under a metre and its drives under
/// a few hundred rad/s, while 1e300 passes every finiteness check and overflows its squares.
constexpr double kMaxLength = 1e3;
constexpr double kMaxSpeed = 1e4;

/// @throw std::invalid_argument "<what> must be finite and > 0, ..." or "... magnitude <=
/// kMaxLength ..." unless 0 < value <= kMaxLength.
inline void requireLength(double value, std::string_view what) {
  requirePositive(value, what);
  requireMagnitudeAtMost(value, kMaxLength, what);
}

}  // namespace spherical_robots
