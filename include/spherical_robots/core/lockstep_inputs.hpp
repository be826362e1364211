#pragma once
// What a lock-step participant (or the plant finishing its step) still waits for: a step request
// lists the topics published since it last worked, with the stamps of their latest messages
// (core/lockstep_sequencer.hpp); it may work once every listed topic it subscribes to has
// delivered a message at least that recent. The transport may deliver a message before or after
// the request, so received stamps are kept per topic. Stamps are integer nanoseconds.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "spherical_robots/core/lockstep_sequencer.hpp"

namespace spherical_robots {

class LockstepInputs {
 public:
  /// @param subscriptions resolved names of the topics this node reads.
  explicit LockstepInputs(std::vector<std::string> subscriptions);

  /// A message stamped `stamp` [ns] arrived on `topic`.
  void received(const std::string& topic, std::int64_t stamp);
  /// Waits for the listed inputs among the subscriptions (others are not this node's).
  void expect(const std::vector<PublishedTopic>& inputs);
  /// Every expected message has arrived.
  bool satisfied() const;
  /// The expected topics that have not delivered yet (for a log line when a wait is long).
  std::vector<std::string> missing() const;

 private:
  std::vector<std::string> subscriptions_;
  std::map<std::string, std::int64_t> received_;
  std::map<std::string, std::int64_t> expected_;
};

}  // namespace spherical_robots
