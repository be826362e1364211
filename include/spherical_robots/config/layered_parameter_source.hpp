#pragma once
// Parameters from several sources, later ones overriding earlier ones key by key, as loading one
// YAML file after another onto the ROS parameter server does (launch/roller_stack.launch loads
// config/terrain.yaml, then config/roller.yaml): sphere_sim reads a stack's configuration as its
// nodes see it.

#include <memory>
#include <vector>

#include "spherical_robots/config/parameter_source.hpp"

namespace spherical_robots::config {

class LayeredParameterSource final : public ParameterSource {
 public:
  /// @param layers in load order, none null. @throw std::invalid_argument if empty or one is null.
  explicit LayeredParameterSource(std::vector<std::unique_ptr<ParameterSource>> layers);

  /// The value of the last layer that holds the key.
  std::optional<double> number(const std::string& key) const override;
  std::optional<std::string> text(const std::string& key) const override;
  std::optional<std::vector<double>> numbers(const std::string& key) const override;
  std::optional<std::vector<std::string>> texts(const std::string& key) const override;
  /// The keys of the dictionary at key in every layer that holds one, each once.
  std::optional<std::vector<std::string>> keys(const std::string& key) const override;
  /// "a.yaml + b.yaml"
  std::string origin() const override;
  /// Through the last layer, the one a user overrides the others with.
  void warn(const std::string& message) const override;

 private:
  /// The value of the topmost layer that has key.
  template <typename Value>
  std::optional<Value> topmost(std::optional<Value> (ParameterSource::*get)(const std::string&) const,
                               const std::string& key) const {
    for (auto layer = layers_.rbegin(); layer != layers_.rend(); ++layer)
      if (std::optional<Value> value = ((**layer).*get)(key)) return value;
    return std::nullopt;
  }

  std::vector<std::unique_ptr<ParameterSource>> layers_;
};

}  // namespace spherical_robots::config
