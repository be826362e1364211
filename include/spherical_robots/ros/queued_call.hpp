#pragma once
// A function as a roscpp callback, to be added to a callback queue: it runs on the thread that
// serves the queue, after what was queued before it.

#include <boost/make_shared.hpp>
#include <ros/callback_queue_interface.h>

#include <utility>

namespace spherical_robots {

template <typename Work>
class QueuedCall : public ros::CallbackInterface {
 public:
  explicit QueuedCall(Work work) : work_(std::move(work)) {}
  CallResult call() override {
    work_();
    return Success;
  }

 private:
  Work work_;
};

/// `work` (any callable, move-only ones included) wrapped for ros::CallbackQueueInterface::addCallback.
template <typename Work>
boost::shared_ptr<QueuedCall<Work>> queuedCall(Work work) {
  return boost::make_shared<QueuedCall<Work>>(std::move(work));
}

}  // namespace spherical_robots
