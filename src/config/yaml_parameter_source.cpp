#include "spherical_robots/config/yaml_parameter_source.hpp"

#include <sstream>
#include <stdexcept>
#include <utility>

namespace spherical_robots::config {

YamlParameterSource::YamlParameterSource(const std::string& path, Warn warn)
    : path_(path), warn_(std::move(warn)) {
  try {
    root_ = YAML::LoadFile(path);
  } catch (const YAML::Exception& error) {
    throw std::invalid_argument("cannot read parameters from '" + path + "': " + error.what());
  }
}

void YamlParameterSource::warn(const std::string& message) const {
  if (warn_)
    warn_(message);
  else
    ParameterSource::warn(message);
}

YAML::Node YamlParameterSource::find(const std::string& key) const {
  // Const lookups and reset(): a non-const operator[] or operator= would modify the tree.
  YAML::Node node;
  node.reset(root_);
  std::istringstream parts(key);
  std::string part;
  while (std::getline(parts, part, '/')) {
    if (part.empty()) continue;
    if (!node.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
    const YAML::Node child = static_cast<const YAML::Node&>(node)[part];
    if (!child.IsDefined()) return YAML::Node(YAML::NodeType::Undefined);
    node.reset(child);
  }
  return node;
}

std::optional<double> YamlParameterSource::number(const std::string& key) const {
  const YAML::Node node = find(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  try {
    if (!node.IsScalar()) throw YAML::Exception(YAML::Mark(), "not a scalar");
    return node.as<double>();
  } catch (const YAML::Exception&) {
    std::ostringstream message;
    message << path_ << ": parameter '" << key << "' must be a number, got '"
            << YAML::Dump(node) << "'";
    throw std::invalid_argument(message.str());
  }
}

std::optional<std::string> YamlParameterSource::text(const std::string& key) const {
  const YAML::Node node = find(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  if (!node.IsScalar()) {
    throw std::invalid_argument(path_ + ": parameter '" + key + "' must be a string");
  }
  return node.as<std::string>();
}

std::optional<std::vector<double>> YamlParameterSource::numbers(const std::string& key) const {
  const YAML::Node node = find(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  std::vector<double> result;
  try {
    if (!node.IsSequence()) throw YAML::Exception(YAML::Mark(), "not a list");
    for (const YAML::Node& item : node) {
      if (!item.IsScalar()) throw YAML::Exception(YAML::Mark(), "not a scalar");
      result.push_back(item.as<double>());
    }
  } catch (const YAML::Exception&) {
    std::ostringstream message;
    message << path_ << ": parameter '" << key << "' must be a list of numbers, got '"
            << YAML::Dump(node) << "'";
    throw std::invalid_argument(message.str());
  }
  return result;
}

std::optional<std::vector<std::string>> YamlParameterSource::texts(const std::string& key) const {
  const YAML::Node node = find(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  std::vector<std::string> result;
  for (const YAML::Node& item : node) {
    if (!node.IsSequence() || !item.IsScalar()) break;
    result.push_back(item.as<std::string>());
  }
  if (!node.IsSequence() || result.size() != node.size())
    throw std::invalid_argument(path_ + ": parameter '" + key + "' must be a list of strings, got '" +
                                YAML::Dump(node) + "'");
  return result;
}

std::optional<std::vector<std::string>> YamlParameterSource::keys(const std::string& key) const {
  const YAML::Node node = find(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  if (!node.IsMap()) {
    throw std::invalid_argument(path_ + ": parameter '" + key + "' must be a dictionary, got '" +
                                YAML::Dump(node) + "'");
  }
  std::vector<std::string> result;
  for (const auto& entry : node) {
    // A YAML key may be a list or a dictionary ("[1, 2]: x"); a parameter's name is a word.
    if (!entry.first.IsScalar()) {
      std::ostringstream message;
      message << path_ << ": line " << entry.first.Mark().line + 1 << ": a key of '" << key
              << "' is '" << YAML::Dump(entry.first) << "', expected a name";
      throw std::invalid_argument(message.str());
    }
    result.push_back(entry.first.Scalar());
  }
  return result;
}

}  // namespace spherical_robots::config
