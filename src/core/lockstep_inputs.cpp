#include "spherical_robots/core/lockstep_inputs.hpp"

#include <algorithm>
#include <utility>

namespace spherical_robots {

LockstepInputs::LockstepInputs(std::vector<std::string> subscriptions)
    : subscriptions_(std::move(subscriptions)) {}

void LockstepInputs::received(const std::string& topic, std::int64_t stamp,
                              const std::string& publisher) {
  auto [it, inserted] = received_.emplace(std::make_pair(topic, publisher), stamp);
  if (!inserted) it->second = std::max(it->second, stamp);
}

void LockstepInputs::expect(const std::vector<PublishedTopic>& inputs) {
  expected_.clear();
  for (const PublishedTopic& input : inputs)
    if (std::find(subscriptions_.begin(), subscriptions_.end(), input.topic) != subscriptions_.end())
      expected_[input.topic] = input;
}

bool LockstepInputs::arrived(const std::string& topic, const PublishedTopic& expected) const {
  for (auto it = received_.lower_bound({topic, expected.publisher});
       it != received_.end() && it->first.first == topic; ++it) {
    if (!expected.publisher.empty() && it->first.second != expected.publisher) break;
    if (it->second >= expected.stamp) return true;
  }
  return false;
}

bool LockstepInputs::satisfied() const {
  return std::all_of(expected_.begin(), expected_.end(),
                     [this](const auto& expected) { return arrived(expected.first, expected.second); });
}

std::optional<std::string> LockstepInputs::expectedPublisher(const std::string& topic) const {
  const auto it = expected_.find(topic);
  if (it == expected_.end()) return std::nullopt;
  return it->second.publisher;
}

std::vector<std::string> LockstepInputs::missing() const {
  std::vector<std::string> topics;
  for (const auto& [topic, expected] : expected_)
    if (!arrived(topic, expected)) topics.push_back(topic);
  return topics;
}

}  // namespace spherical_robots
