#pragma once
// The latest message of one input topic from each of its publishers, for a participant that
// works on the message stamped with the step's time (MessageDrivenWork, docs/lockstep.md): the
// step's input is the message of the publisher its request names, so that another node's message
// stamped with the step's time does not stand in for the loop's. Stamps are integer nanoseconds.
// No ROS.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace spherical_robots {

template <typename Message>
class LatestPerPublisher {
 public:
  /// `message`, stamped `stamp` [ns], arrived from `publisher`; it replaces that publisher's last.
  void keep(const std::string& publisher, std::int64_t stamp, Message message) {
    held_.insert_or_assign(publisher, Held{stamp, ++arrivals_, std::move(message)});
  }

  /// The step's input at `stamp` [ns]: the message stamped `stamp` from `publisher`, or, where
  /// the request names no publisher (empty; a plant older than the field), the latest to arrive
  /// of those stamped `stamp`. nullptr if there is none.
  const Message* at(std::int64_t stamp, const std::string& publisher) const {
    if (!publisher.empty()) {
      const auto it = held_.find(publisher);
      return it != held_.end() && it->second.stamp == stamp ? &it->second.message : nullptr;
    }
    const Held* latest = nullptr;
    for (const auto& [name, held] : held_)
      if (held.stamp == stamp && (!latest || held.arrival > latest->arrival)) latest = &held;
    return latest ? &latest->message : nullptr;
  }

 private:
  struct Held {
    std::int64_t stamp;
    std::uint64_t arrival;  ///< order of arrival, over all publishers
    Message message;
  };
  std::map<std::string, Held> held_;
  std::uint64_t arrivals_ = 0;
};

}  // namespace spherical_robots
