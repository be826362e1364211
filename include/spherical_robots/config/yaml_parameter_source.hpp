#pragma once
#include <yaml-cpp/yaml.h>

#include <functional>

#include "spherical_robots/config/parameter_source.hpp"

namespace spherical_robots::config {

/// Parameters from a YAML file; keys are '/'-separated paths into its maps.
class YamlParameterSource final : public ParameterSource {
 public:
  using Warn = std::function<void(const std::string&)>;
  /// @param warn receives warn()'s messages (empty: standard error).
  /// @throw std::invalid_argument if the file cannot be read or parsed (message names the file).
  explicit YamlParameterSource(const std::string& path, Warn warn = {});
  std::optional<double> number(const std::string& key) const override;
  std::optional<std::string> text(const std::string& key) const override;
  std::optional<std::vector<double>> numbers(const std::string& key) const override;
  std::optional<std::vector<std::string>> texts(const std::string& key) const override;
  std::optional<std::vector<std::string>> keys(const std::string& key) const override;
  std::string origin() const override { return path_; }
  void warn(const std::string& message) const override;

 private:
  YAML::Node find(const std::string& key) const;
  std::string path_;
  YAML::Node root_;
  Warn warn_;
};

}  // namespace spherical_robots::config
