#pragma once
// An enumeration's names, both ways, from one table kept beside the enumeration: parameters and
// command-line options name enumerators ("3R", "paper"), and an unknown name is an error that
// lists the known ones.

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace spherical_robots {

template <typename Enum, std::size_t N>
using EnumNames = std::array<std::pair<Enum, std::string_view>, N>;

/// @throw std::invalid_argument "unknown <kind> '<name>' (expected a, b or c)" for a name not in
/// the table.
template <typename Enum, std::size_t N>
Enum enumFromName(const EnumNames<Enum, N>& names, const std::string& name, std::string_view kind) {
  std::string expected;
  for (std::size_t i = 0; i < N; ++i) {
    if (names[i].second == name) return names[i].first;
    const char* separator = i == 0 ? "" : i + 1 == N ? " or " : ", ";
    expected += separator + std::string(names[i].second);
  }
  throw std::invalid_argument("unknown " + std::string(kind) + " '" + name + "' (expected " +
                              expected + ")");
}

/// @throw std::invalid_argument for a value not in the table (a cast from a bad integer).
template <typename Enum, std::size_t N>
std::string enumName(const EnumNames<Enum, N>& names, Enum value) {
  for (const auto& [enumerator, name] : names)
    if (enumerator == value) return std::string(name);
  throw std::invalid_argument("enumerator " + std::to_string(static_cast<int>(value)) +
                              " has no name");
}

}  // namespace spherical_robots
