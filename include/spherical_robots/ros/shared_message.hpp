#pragma once
// Messages of the loop published by shared pointer: within one process (the nodes of a stack as
// nodelets in one manager) roscpp hands a subscriber that very object, neither serialised nor
// copied; a message published by reference is serialised, and deserialised again by every
// subscriber in the process. Published once, the object is never changed again.

#include <boost/make_shared.hpp>
#include <boost/shared_ptr.hpp>

#include <type_traits>
#include <utility>

namespace spherical_robots {

/// `message` moved (or copied) to the heap, for ros::Publisher::publish.
template <typename Message>
boost::shared_ptr<const std::decay_t<Message>> shared(Message&& message) {
  return boost::make_shared<const std::decay_t<Message>>(std::forward<Message>(message));
}

}  // namespace spherical_robots
