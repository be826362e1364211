#pragma once
// Every node class of the package as a nodelet (nodelet_plugins.xml): the class a node's main()
// runs (run_node.hpp), constructed inside a nodelet manager instead of a process of its own, so
// that messages between the nodes of a stack pass as shared pointers within one process.

#include <nodelet/nodelet.h>
#include <ros/callback_queue.h>

#include <atomic>
#include <exception>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include "spherical_robots/ros/queued_call.hpp"

namespace spherical_robots {

/// The one thread that runs every callback of this package's nodelets in a manager, and their
/// construction and destruction, from one queue. The nodes of a stack then work one at a time,
/// as lock-step has them work anyway, and a message from one to another is the next callback on
/// the same thread rather than a thread to wake (docs/lockstep.md, "Nodelets"). Construction on
/// it also means that no callback of a node runs before its constructor has returned, as in a
/// process, where ros::spin() starts after it. Shared by the nodelets; it ends with the last.
class NodeletThread {
 public:
  static std::shared_ptr<NodeletThread> shared() {
    static std::mutex mutex;
    static std::weak_ptr<NodeletThread> instance;
    std::lock_guard<std::mutex> lock(mutex);
    std::shared_ptr<NodeletThread> thread = instance.lock();
    if (!thread) instance = thread = std::shared_ptr<NodeletThread>(new NodeletThread);
    return thread;
  }
  NodeletThread(const NodeletThread&) = delete;
  NodeletThread& operator=(const NodeletThread&) = delete;
  ~NodeletThread() {
    running_ = false;
    thread_.join();
  }

  ros::CallbackQueue* queue() { return &queue_; }

  /// Runs `work` on the thread, after the callbacks queued before it, and waits for it.
  /// @throw what `work` throws. Not from the thread itself.
  void run(std::function<void()> work) {
    std::packaged_task<void()> task(std::move(work));
    std::future<void> done = task.get_future();
    queue_.addCallback(queuedCall(std::move(task)));
    done.get();
  }

 private:
  // Not stopped by ros::shutdown(), so that the nodes are still destroyed on it afterwards.
  NodeletThread()
      : thread_([this] {
          while (running_) queue_.callAvailable(ros::WallDuration(0.1));
        }) {}

  std::atomic<bool> running_{true};
  ros::CallbackQueue queue_;
  std::thread thread_;  // last: it starts once the queue exists
};

/// Constructs Node(nh, private nh) with the nodelet's handles (its name, namespace, remappings
/// and parameters) on the NodeletThread, which runs its callbacks. A construction error is a
/// start-up failure, as in a process: NODELET_FATAL "<name> cannot start: <what>", and the
/// manager refuses the nodelet, so that `nodelet load` exits with an error (and a required one
/// ends the stack).
template <typename Node>
class NodeNodelet : public nodelet::Nodelet {
 public:
  ~NodeNodelet() override {
    if (thread_) thread_->run([this] { node_.reset(); });
  }

 private:
  void onInit() override {
    thread_ = NodeletThread::shared();
    ros::NodeHandle nh = getNodeHandle(), pnh = getPrivateNodeHandle();
    nh.setCallbackQueue(thread_->queue());
    pnh.setCallbackQueue(thread_->queue());
    try {
      thread_->run([&] { node_.emplace(nh, pnh); });
    } catch (const std::exception& e) {
      NODELET_FATAL_STREAM(getName() << " cannot start: " << e.what());
      throw;
    }
  }

  std::shared_ptr<NodeletThread> thread_;
  std::optional<Node> node_;
};

}  // namespace spherical_robots
