#pragma once
// What a lock-step participant (or the plant finishing its step) still waits for: a step request
// lists the topics published since it last worked, with the stamps of their latest messages and
// their publishers (core/lockstep_sequencer.hpp); it may work once every listed topic it
// subscribes to has delivered a message at least that recent from that publisher. The transport
// may deliver a message before or after the request, so received stamps are kept per topic and
// publisher. Stamps are integer nanoseconds.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "spherical_robots/core/lockstep_sequencer.hpp"

namespace spherical_robots {

class LockstepInputs {
 public:
  /// @param subscriptions resolved names of the topics this node reads.
  explicit LockstepInputs(std::vector<std::string> subscriptions);

  /// A message stamped `stamp` [ns] arrived on `topic` from `publisher` (the transport's caller
  /// id), whether or not the node accepted it: its publisher's message, bad or good, is the one the
  /// step waits for.
  void received(const std::string& topic, std::int64_t stamp, const std::string& publisher);
  /// Waits for the listed inputs among the subscriptions (others are not this node's).
  void expect(const std::vector<PublishedTopic>& inputs);
  /// Every expected message has arrived (from its publisher, or from any where none is named).
  bool satisfied() const;
  /// The publisher whose message on `topic` the current request waits for: its caller id, empty
  /// where the request names none (any publisher's will do); nullopt if the request does not
  /// list the topic (nothing was published on it in the loop since this node last worked).
  std::optional<std::string> expectedPublisher(const std::string& topic) const;
  /// The expected topics that have not delivered yet (for a log line when a wait is long).
  std::vector<std::string> missing() const;

 private:
  bool arrived(const std::string& topic, const PublishedTopic& expected) const;

  std::vector<std::string> subscriptions_;
  std::map<std::pair<std::string, std::string>, std::int64_t> received_;  ///< (topic, publisher)
  std::map<std::string, PublishedTopic> expected_;
};

}  // namespace spherical_robots
