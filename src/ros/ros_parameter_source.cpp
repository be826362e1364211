#include "spherical_robots/ros/ros_parameter_source.hpp"

#include <XmlRpcValue.h>
#include <ros/console.h>

#include <sstream>
#include <stdexcept>

#include "spherical_robots/config/robot_description.hpp"

namespace spherical_robots {
namespace {

[[noreturn]] void throwBadType(const std::string& name, XmlRpc::XmlRpcValue& value,
                               const char* expected) {
  std::ostringstream what;
  what << "parameter " << name << " = " << value.toXml() << " is not " << expected;
  throw std::invalid_argument(what.str());
}

}  // namespace

RosParameterSource::RosParameterSource(const ros::NodeHandle& nh) : nh_(nh) {}

std::optional<double> RosParameterSource::number(const std::string& key) const {
  XmlRpc::XmlRpcValue value;
  if (!nh_.getParam(key, value)) return std::nullopt;
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeDouble:
      return static_cast<double>(value);
    case XmlRpc::XmlRpcValue::TypeInt:
      return static_cast<double>(static_cast<int>(value));
    default:
      throwBadType(resolve(key), value, "a number");
  }
}

std::optional<std::string> RosParameterSource::text(const std::string& key) const {
  XmlRpc::XmlRpcValue value;
  if (!nh_.getParam(key, value)) return std::nullopt;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeString) throwBadType(resolve(key), value, "a string");
  return static_cast<std::string>(value);
}

std::optional<std::vector<double>> RosParameterSource::numbers(const std::string& key) const {
  XmlRpc::XmlRpcValue value;
  if (!nh_.getParam(key, value)) return std::nullopt;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) throwBadType(resolve(key), value, "a list");
  std::vector<double> result;
  for (int i = 0; i < value.size(); ++i) {
    XmlRpc::XmlRpcValue& item = value[i];
    if (item.getType() == XmlRpc::XmlRpcValue::TypeDouble)
      result.push_back(static_cast<double>(item));
    else if (item.getType() == XmlRpc::XmlRpcValue::TypeInt)
      result.push_back(static_cast<double>(static_cast<int>(item)));
    else
      throwBadType(resolve(key) + "[" + std::to_string(i) + "]", item, "a number");
  }
  return result;
}

std::optional<std::vector<std::string>> RosParameterSource::texts(const std::string& key) const {
  XmlRpc::XmlRpcValue value;
  if (!nh_.getParam(key, value)) return std::nullopt;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray) throwBadType(resolve(key), value, "a list");
  std::vector<std::string> result;
  for (int i = 0; i < value.size(); ++i) {
    XmlRpc::XmlRpcValue& item = value[i];
    if (item.getType() != XmlRpc::XmlRpcValue::TypeString)
      throwBadType(resolve(key) + "[" + std::to_string(i) + "]", item, "a string");
    result.push_back(static_cast<std::string>(item));
  }
  return result;
}

std::optional<std::vector<std::string>> RosParameterSource::keys(const std::string& key) const {
  XmlRpc::XmlRpcValue value;
  if (!nh_.getParam(key, value)) return std::nullopt;
  if (value.getType() != XmlRpc::XmlRpcValue::TypeStruct)
    throwBadType(resolve(key), value, "a dictionary");
  std::vector<std::string> result;
  for (auto entry = value.begin(); entry != value.end(); ++entry) result.push_back(entry->first);
  return result;
}

std::string RosParameterSource::origin() const { return nh_.getNamespace(); }

void RosParameterSource::warn(const std::string& message) const { ROS_WARN_STREAM(message); }

std::string RosParameterSource::resolve(const std::string& key) const { return nh_.resolveName(key); }

std::string robotDescription(const ros::NodeHandle& nh) {
  const auto urdf = RosParameterSource(nh).text("robot_description");
  if (!urdf)
    throw std::invalid_argument("parameter " + nh.resolveName("robot_description") +
                                " (the URDF) is not set");
  return *urdf;
}

double radiusFromRobotDescription(const ros::NodeHandle& nh) {
  return fromRobotDescription(nh, [](const std::string& urdf) {
    return config::sphereRadiusFromUrdf(urdf, "shell");
  });
}

}  // namespace spherical_robots
