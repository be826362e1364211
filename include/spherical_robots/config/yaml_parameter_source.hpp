#pragma once
#include <yaml-cpp/yaml.h>

#include <functional>
#include <set>
#include <string>
#include <vector>

#include "spherical_robots/config/parameter_source.hpp"

namespace spherical_robots::config {

/// Parameters from a YAML file; keys are '/'-separated paths into its maps.
class YamlParameterSource final : public ParameterSource {
 public:
  using Warn = std::function<void(const std::string&)>;
  /// @param warn receives warn()'s messages (empty: standard error).
  /// An empty file is warned of (every parameter takes its default).
  /// @throw std::invalid_argument if the file cannot be read or parsed, its top level is not a
  /// dictionary, or a dictionary gives a key twice (the message names the file and the line).
  explicit YamlParameterSource(const std::string& path, Warn warn = {});
  std::optional<double> number(const std::string& key) const override;
  std::optional<std::string> text(const std::string& key) const override;
  std::optional<std::vector<double>> numbers(const std::string& key) const override;
  std::optional<std::vector<std::string>> texts(const std::string& key) const override;
  std::optional<std::vector<std::string>> keys(const std::string& key) const override;
  std::string origin() const override { return path_; }
  void warn(const std::string& message) const override;
  /// A key of the file and the line it is on (1-based).
  struct Key {
    std::string key;
    int line;
  };
  /// The keys under section ("" the whole file) whose values no number(), text(), numbers() or
  /// texts() has read yet: after the loaders ran, parameters that nothing uses, misspelt ones
  /// among them.
  std::vector<Key> unreadKeys(const std::string& section) const;
  /// Whether the file gives key (without counting it as read).
  bool gives(const std::string& key) const { return find(key).IsDefined(); }

 private:
  /// The node at key. @throw std::invalid_argument if a part of key is a value, not a dictionary.
  YAML::Node find(const std::string& key) const;
  /// find(key), recording that key's value was read.
  YAML::Node value(const std::string& key) const;
  std::string path_;
  YAML::Node root_;
  Warn warn_;
  mutable std::set<std::string> read_;
};

}  // namespace spherical_robots::config
