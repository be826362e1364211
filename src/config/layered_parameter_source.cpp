#include "spherical_robots/config/layered_parameter_source.hpp"

#include <algorithm>
#include <stdexcept>

namespace spherical_robots::config {

LayeredParameterSource::LayeredParameterSource(
    std::vector<std::unique_ptr<ParameterSource>> layers)
    : layers_(std::move(layers)) {
  if (layers_.empty() || std::any_of(layers_.begin(), layers_.end(),
                                     [](const auto& layer) { return layer == nullptr; }))
    throw std::invalid_argument("layered parameters: every layer must exist, and one at least");
}

std::optional<double> LayeredParameterSource::number(const std::string& key) const {
  return topmost(&ParameterSource::number, key);
}

std::optional<std::string> LayeredParameterSource::text(const std::string& key) const {
  return topmost(&ParameterSource::text, key);
}

std::optional<std::vector<double>> LayeredParameterSource::numbers(const std::string& key) const {
  return topmost(&ParameterSource::numbers, key);
}

std::optional<std::vector<std::string>> LayeredParameterSource::texts(const std::string& key) const {
  return topmost(&ParameterSource::texts, key);
}

std::optional<std::vector<std::string>> LayeredParameterSource::keys(const std::string& key) const {
  std::optional<std::vector<std::string>> all;
  for (const auto& layer : layers_) {
    const std::optional<std::vector<std::string>> some = layer->keys(key);
    if (!some) continue;
    if (!all) all.emplace();
    for (const std::string& name : *some)
      if (std::find(all->begin(), all->end(), name) == all->end()) all->push_back(name);
  }
  return all;
}

std::string LayeredParameterSource::origin() const {
  std::string names;
  for (const auto& layer : layers_) names += (names.empty() ? "" : " + ") + layer->origin();
  return names;
}

void LayeredParameterSource::warn(const std::string& message) const { layers_.back()->warn(message); }

}  // namespace spherical_robots::config
