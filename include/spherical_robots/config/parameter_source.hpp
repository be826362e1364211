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
  /// Tells the user of a parameter that is read but should change (a deprecated name, see
  /// renamedNumber); the loaders call it once, at start. Standard error unless overridden: the
  /// parameter server's source logs it (rosconsole).
  virtual void warn(const std::string& message) const;
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

/// A parameter's name, and the one it had before a release renamed it (docs/migration.md); the old
/// name is still read for one release.
struct RenamedKey {
  std::string key;
  std::string old_key;
};

/// check(source, name, fallback) of a renamed parameter (check: finiteNumber, positiveNumber...):
/// at name.key; else at name.old_key; else fallback. A set old_key is reported through
/// source.warn, naming both names and the value used: the new name's when both are set.
double renamedNumber(const ParameterSource& source, const RenamedKey& name, double fallback,
                     double (*check)(const ParameterSource&, const std::string&, double));

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
