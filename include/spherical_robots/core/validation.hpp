#pragma once
// Input checks shared by every core function: a bad number is rejected where it enters, with a
// message naming it, instead of travelling on as a NaN.

#include <string_view>

namespace spherical_robots {

/// @throw std::invalid_argument "<what> must be finite, got <value>" unless value is finite.
void requireFinite(double value, std::string_view what);

/// @throw std::invalid_argument "<what> must be finite and > 0, got <value>" unless it is.
void requirePositive(double value, std::string_view what);

}  // namespace spherical_robots
