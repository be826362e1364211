#pragma once
// A read-only view of nested parameters ("gains/3R/k_theta"), so one parser serves the YAML files
// (sphere_sim, tests) and the ROS parameter server (nodes).

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace spherical_robots::config {

class ParameterSource {
 public:
  virtual ~ParameterSource() = default;
  /// The number at key, nullopt if absent. @throw std::invalid_argument if present but not a number.
  virtual std::optional<double> number(const std::string& key) const = 0;
  /// The string at key, nullopt if absent. @throw std::invalid_argument if present but not a string.
  virtual std::optional<std::string> text(const std::string& key) const = 0;
  /// The list of numbers at key, nullopt if absent.
  /// @throw std::invalid_argument if present but not a list of numbers.
  virtual std::optional<std::vector<double>> numbers(const std::string& key) const = 0;
  /// The list of strings at key, nullopt if absent.
  /// @throw std::invalid_argument if present but not a list of strings.
  virtual std::optional<std::vector<std::string>> texts(const std::string& key) const = 0;
  /// The keys of the dictionary at key ("" the root), nullopt if absent.
  /// @throw std::invalid_argument if present but not a dictionary.
  virtual std::optional<std::vector<std::string>> keys(const std::string& key) const = 0;
  /// Where the values come from, for error messages ("config/terrain.yaml", "/robot1/controller").
  virtual std::string origin() const = 0;
};

/// The number at key, or fallback if absent; throws std::invalid_argument naming the key, the
/// value and the origin if the value is not finite.
double finiteNumber(const ParameterSource& source, const std::string& key, double fallback);

/// finiteNumber that must also be > 0; the message names the key, the value and the limit.
double positiveNumber(const ParameterSource& source, const std::string& key, double fallback);

/// finiteNumber that must also be >= 0.
double nonNegativeNumber(const ParameterSource& source, const std::string& key, double fallback);

/// finiteNumber that must also be a whole number >= minimum (and fit an int).
int wholeNumber(const ParameterSource& source, const std::string& key, int fallback, int minimum);

/// The string at key (or fallback if absent) turned into a value by parse, e.g.
/// terrain::robotTypeFromString; parse's std::invalid_argument is rethrown naming the origin, the
/// key and the value.
template <typename Parse>
auto parsedText(const ParameterSource& source, const std::string& key, const std::string& fallback,
                Parse parse) {
  const std::string text = source.text(key).value_or(fallback);
  try {
    return parse(text);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(source.origin() + ": parameter '" + key + "' = '" + text +
                                "': " + e.what());
  }
}

}  // namespace spherical_robots::config
