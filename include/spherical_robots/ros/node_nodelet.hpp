#pragma once
// Every node class of the package as a nodelet (nodelet_plugins.xml): the class a node's main()
// runs (run_node.hpp), constructed inside a nodelet manager instead of a process of its own, so
// that messages between the nodes of a stack pass as shared pointers within one process.

#include <nodelet/nodelet.h>
#include <ros/callback_queue.h>
#include <ros/spinner.h>

#include <exception>
#include <optional>

namespace spherical_robots {

/// Constructs Node(nh, private nh) with the nodelet's handles (its name, namespace, remappings
/// and parameters). A construction error is a start-up failure, as in a process: NODELET_FATAL
/// "<name> cannot start: <what>", and the manager refuses the nodelet, so that `nodelet load`
/// exits with an error (and a required one ends the stack).
template <typename Node>
class NodeNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    // The node's callbacks run on a queue of its own, served by one thread that starts only once
    // the node is constructed, as a process's ros::spin() does. On the nodelet's own queue the
    // manager's workers would serve them while onInit() still runs, and a subscription or timer
    // callback could reach a node that is half built.
    ros::NodeHandle nh = getNodeHandle(), pnh = getPrivateNodeHandle();
    nh.setCallbackQueue(&queue_);
    pnh.setCallbackQueue(&queue_);
    try {
      node_.emplace(nh, pnh);
    } catch (const std::exception& e) {
      NODELET_FATAL_STREAM(getName() << " cannot start: " << e.what());
      throw;
    }
    spinner_.emplace(1, &queue_);
    spinner_->start();
  }

  // Destroyed in reverse order: the spinner's thread is stopped and joined before the node goes,
  // and the node's subscriptions and timers leave the queue before the queue goes.
  ros::CallbackQueue queue_;
  std::optional<Node> node_;
  std::optional<ros::AsyncSpinner> spinner_;
};

}  // namespace spherical_robots
