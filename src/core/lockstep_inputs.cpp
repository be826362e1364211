#include "spherical_robots/core/lockstep_inputs.hpp"

#include <algorithm>
#include <utility>

namespace spherical_robots {

LockstepInputs::LockstepInputs(std::vector<std::string> subscriptions)
    : subscriptions_(std::move(subscriptions)) {}

void LockstepInputs::received(const std::string& topic, std::int64_t stamp) {
  auto [it, inserted] = received_.emplace(topic, stamp);
  if (!inserted) it->second = std::max(it->second, stamp);
}

void LockstepInputs::expect(const std::vector<PublishedTopic>& inputs) {
  expected_.clear();
  for (const PublishedTopic& input : inputs)
    if (std::find(subscriptions_.begin(), subscriptions_.end(), input.topic) != subscriptions_.end())
      expected_[input.topic] = input.stamp;
}

bool LockstepInputs::satisfied() const {
  return std::all_of(expected_.begin(), expected_.end(), [this](const auto& expected) {
    const auto it = received_.find(expected.first);
    return it != received_.end() && it->second >= expected.second;
  });
}

std::vector<std::string> LockstepInputs::missing() const {
  std::vector<std::string> topics;
  for (const auto& [topic, stamp] : expected_) {
    const auto it = received_.find(topic);
    if (it == received_.end() || it->second < stamp) topics.push_back(topic);
  }
  return topics;
}

}  // namespace spherical_robots
