#include "spherical_robots/config/yaml_parameter_source.hpp"

#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace spherical_robots::config {

namespace {

std::string lineOf(const YAML::Node& node) {
  return node.Mark().is_null() ? "" : " line " + std::to_string(node.Mark().line + 1);
}

std::string joined(const std::string& parent, const std::string& child) {
  return parent.empty() ? child : parent + "/" + child;
}

/// Every key a name, once per dictionary: yaml-cpp keeps a key given twice and reads the first, so
/// a later value, which the author meant, would be silently ignored.
void checkKeys(const YAML::Node& node, const std::string& key, const std::string& path) {
  if (node.IsSequence()) {
    for (const YAML::Node& item : node) checkKeys(item, key, path);
    return;
  }
  if (!node.IsMap()) return;
  std::set<std::string> seen;
  for (const auto& entry : node) {
    // A YAML key may be a list or a dictionary ("[1, 2]: x"); a parameter's name is a word.
    if (!entry.first.IsScalar()) {
      throw std::invalid_argument(path + lineOf(entry.first) + ": " +
                                  (key.empty() ? std::string("a key") : "a key of '" + key + "'") +
                                  " is '" + YAML::Dump(entry.first) + "', expected a name");
    }
    const std::string name = entry.first.Scalar();
    if (!seen.insert(name).second) {
      throw std::invalid_argument(path + lineOf(entry.first) + ": parameter '" + joined(key, name) +
                                  "' is given twice");
    }
    checkKeys(entry.second, joined(key, name), path);
  }
}

}  // namespace

YamlParameterSource::YamlParameterSource(const std::string& path, Warn warn)
    : path_(path), warn_(std::move(warn)) {
  try {
    root_ = YAML::LoadFile(path);
  } catch (const YAML::Exception& error) {
    throw std::invalid_argument("cannot read parameters from '" + path + "': " + error.what());
  }
  if (root_.IsNull()) {
    this->warn(path + " holds no parameters: every parameter takes its default");
  } else if (!root_.IsMap()) {
    throw std::invalid_argument(path + lineOf(root_) +
                                ": the top level must be a dictionary of parameters, got '" +
                                YAML::Dump(root_) + "'");
  }
  checkKeys(root_, "", path);
}

std::vector<YamlParameterSource::Key> YamlParameterSource::unreadKeys(
    const std::string& section) const {
  std::vector<Key> unread;
  const std::function<void(const YAML::Node&, const std::string&)> visit =
      [&](const YAML::Node& node, const std::string& key) {
        if (read_.count(key)) return;  // the whole value was read
        if (!node.IsMap()) {
          unread.push_back({key, node.Mark().line + 1});
          return;
        }
        for (const auto& entry : node) visit(entry.second, joined(key, entry.first.Scalar()));
      };
  const YAML::Node node = find(section);
  if (node.IsMap()) {
    for (const auto& entry : node) visit(entry.second, joined(section, entry.first.Scalar()));
  }
  return unread;
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
  std::string part, walked;
  while (std::getline(parts, part, '/')) {
    if (part.empty()) continue;
    if (node.IsNull()) return YAML::Node(YAML::NodeType::Undefined);
    if (!node.IsMap()) {
      // A value where the key needs a dictionary: its parameters would silently take defaults.
      throw std::invalid_argument(path_ + lineOf(node) + ": parameter '" + walked +
                                  "' must be a dictionary (holding '" + key + "'), got '" +
                                  YAML::Dump(node) + "'");
    }
    const YAML::Node child = static_cast<const YAML::Node&>(node)[part];
    if (!child.IsDefined()) return YAML::Node(YAML::NodeType::Undefined);
    node.reset(child);
    walked = joined(walked, part);
  }
  return node;
}

YAML::Node YamlParameterSource::value(const std::string& key) const {
  const YAML::Node node = find(key);
  std::string normalised;
  std::istringstream parts(key);
  for (std::string part; std::getline(parts, part, '/');) {
    if (!part.empty()) normalised = joined(normalised, part);
  }
  read_.insert(normalised);
  return node;
}

std::optional<double> YamlParameterSource::number(const std::string& key) const {
  const YAML::Node node = value(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  try {
    if (!node.IsScalar()) throw YAML::Exception(YAML::Mark(), "not a scalar");
    return node.as<double>();
  } catch (const YAML::Exception&) {
    std::ostringstream message;
    message << path_ << lineOf(node) << ": parameter '" << key << "' must be a number, got '"
            << YAML::Dump(node) << "'";
    throw std::invalid_argument(message.str());
  }
}

std::optional<std::string> YamlParameterSource::text(const std::string& key) const {
  const YAML::Node node = value(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  if (!node.IsScalar()) {
    throw std::invalid_argument(path_ + lineOf(node) + ": parameter '" + key + "' must be a string");
  }
  return node.as<std::string>();
}

std::optional<std::vector<double>> YamlParameterSource::numbers(const std::string& key) const {
  const YAML::Node node = value(key);
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
    message << path_ << lineOf(node) << ": parameter '" << key << "' must be a list of numbers, got '"
            << YAML::Dump(node) << "'";
    throw std::invalid_argument(message.str());
  }
  return result;
}

std::optional<std::vector<std::string>> YamlParameterSource::texts(const std::string& key) const {
  const YAML::Node node = value(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  std::vector<std::string> result;
  for (const YAML::Node& item : node) {
    if (!node.IsSequence() || !item.IsScalar()) break;
    result.push_back(item.as<std::string>());
  }
  if (!node.IsSequence() || result.size() != node.size())
    throw std::invalid_argument(path_ + lineOf(node) + ": parameter '" + key + "' must be a list of strings, got '" +
                                YAML::Dump(node) + "'");
  return result;
}

std::optional<std::vector<std::string>> YamlParameterSource::keys(const std::string& key) const {
  const YAML::Node node = find(key);
  if (!node.IsDefined() || node.IsNull()) return std::nullopt;
  if (!node.IsMap()) {
    throw std::invalid_argument(path_ + lineOf(node) + ": parameter '" + key + "' must be a dictionary, got '" +
                                YAML::Dump(node) + "'");
  }
  std::vector<std::string> result;
  for (const auto& entry : node) result.push_back(entry.first.Scalar());  // names: the constructor
  return result;
}

}  // namespace spherical_robots::config
