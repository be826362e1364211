#pragma once
// The nav_msgs/Path a node is sent to follow: taken in from its topic, transformed by tf into the
// node's frame, checked, sampled; counted and reported on /diagnostics.

#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "spherical_robots/core/input_health.hpp"
#include "spherical_robots/terrain/sampled_path.hpp"

namespace spherical_robots {

/// Paths from the topic `path`; the last one wins. A path in another frame than the node's waits
/// up to tf_timeout of wall time for its transform, and gives way to a newer path meanwhile (counted
/// as refused, so that a sender streaming paths in an unknown frame shows). An accepted path goes
/// to the node's Accept; a refused one is logged naming the sender and the reason, and the node
/// keeps what it follows.
class PathReception {
 public:
  struct Parameters {
    std::string frame;     ///< the node's: the odometry's frame (~odom_frame)
    double tf_timeout;     ///< [s] of wall time (~path_tf_timeout)
    double max_position;   ///< [m] a coordinate beyond it is refused (~max_position)
    double untimed_speed;  ///< [m/s] along a path whose stamps are all equal (~untimed_speed)
  };
  /// An accepted path, its first pose's stamp, the node's time when it arrived, and where it
  /// came from ("<topic> from <publisher> in frame '<frame>'").
  using Accept = std::function<void(std::unique_ptr<terrain::SampledPath> path,
                                    const ros::Time& first_stamp, const ros::Time& received,
                                    const std::string& origin)>;

  /// @param now the node's time; @param kept what the node follows, for a refusal's log line
  /// (empty: nothing); @param updater the node's, updated at once after each path.
  PathReception(ros::NodeHandle nh, Parameters parameters, std::function<ros::Time()> now,
                Accept accept, std::function<std::string()> kept,
                diagnostic_updater::Updater& updater);

  const std::string& topic() const { return topic_; }
  /// The counts and the last refusal; with `following` false, the node is at rest: ERROR after a
  /// refusal, else WARN (waiting). With a path, refusals raise the level while they go on.
  void report(diagnostic_updater::DiagnosticStatusWrapper& status, bool following);

 private:
  /// A received path waiting for its frame's transform.
  struct Pending {
    nav_msgs::Path::ConstPtr msg;
    std::string publisher;
    ros::Time received;  ///< the node's time when it arrived
    ros::WallTime arrived;
  };

  void onPath(const ros::MessageEvent<const nav_msgs::Path>& event);
  /// Takes in the pending path, or refuses it: at once, or once its frame has a transform to the
  /// node's (waiting up to tf_timeout for tf).
  void resolve();
  void refuse(const std::string& reason);

  Parameters parameters_;
  std::function<ros::Time()> now_;
  Accept accept_;
  std::function<std::string()> kept_;
  diagnostic_updater::Updater* updater_;
  std::optional<Pending> pending_;
  InputHealth health_;  ///< refusals, on wall time
  unsigned long accepted_ = 0;
  unsigned long refused_ = 0;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  ros::WallTimer retry_timer_;  ///< retries a pending path while it waits for tf
  ros::Subscriber subscriber_;
  std::string topic_;
};

}  // namespace spherical_robots
