#include "spherical_robots/ros/path_reception.hpp"

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <tf2/exceptions.h>

#include <sstream>
#include <stdexcept>
#include <utility>

#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/terrain_conversions.hpp"

namespace spherical_robots {
namespace {

constexpr double kTfRetryPeriod = 0.05;  // [s] of wall time

}  // namespace

PathReception::PathReception(ros::NodeHandle nh, Parameters parameters, std::function<ros::Time()> now,
                             Accept accept, std::function<std::string()> kept,
                             diagnostic_updater::Updater& updater)
    : parameters_(std::move(parameters)),
      now_(std::move(now)),
      accept_(std::move(accept)),
      kept_(std::move(kept)),
      updater_(&updater),
      tf_listener_(tf_buffer_, nh) {
  retry_timer_ = nh.createWallTimer(ros::WallDuration(kTfRetryPeriod),
                                    [this](const ros::WallTimerEvent&) { resolve(); }, false, false);
  // Latched, the last one wins: a new path replaces the one followed.
  subscriber_ = nh.subscribe("path", 1, &PathReception::onPath, this);
  topic_ = subscriber_.getTopic();
}

void PathReception::onPath(const ros::MessageEvent<const nav_msgs::Path>& event) {
  if (pending_) {
    refuse("replaced by a newer path while waiting for a transform from frame '" +
           pending_->msg->header.frame_id + "'");
  }
  pending_ = Pending{event.getConstMessage(), event.getPublisherName(), now_(), ros::WallTime::now()};
  resolve();
}

void PathReception::resolve() {
  if (!pending_) return;
  const nav_msgs::Path& msg = *pending_->msg;
  const std::string& frame = msg.header.frame_id;
  try {
    if (frame.empty()) {
      throw std::invalid_argument("header.frame_id is empty; the controller's frame is '" +
                                  parameters_.frame + "' (~odom_frame)");
    }
    Eigen::Isometry3d to_frame = Eigen::Isometry3d::Identity();
    if (frame != parameters_.frame) {
      std::string tf_error;
      if (!tf_buffer_.canTransform(parameters_.frame, frame, msg.header.stamp, &tf_error)) {
        const double waited = (ros::WallTime::now() - pending_->arrived).toSec();
        if (waited < parameters_.tf_timeout) {
          retry_timer_.start();
          return;
        }
        std::ostringstream problem;
        problem << "no transform from frame '" << frame << "' to '" << parameters_.frame << "' at "
                << msg.header.stamp.toSec() << " s after " << waited << " s (path_tf_timeout "
                << parameters_.tf_timeout << " s): " << tf_error;
        throw std::invalid_argument(problem.str());
      }
      to_frame = conversions::fromTransform(
          tf_buffer_.lookupTransform(parameters_.frame, frame, msg.header.stamp).transform,
          "transform from '" + frame + "'");
    }
    auto path = std::make_unique<terrain::SampledPath>(terrain::SampledPath::fromStamped(
        conversions::stampedPointsFromPath(msg, to_frame, parameters_.max_position),
        parameters_.untimed_speed));
    accept_(std::move(path), msg.poses.front().header.stamp, pending_->received,
            topic_ + " from " + pending_->publisher + " in frame '" + frame + "'");
    ++accepted_;
    health_.accepted(ros::WallTime::now().toSec());
    updater_->force_update();
  } catch (const std::invalid_argument& e) {
    refuse(e.what());
  } catch (const tf2::TransformException& e) {
    refuse(std::string("tf: ") + e.what());
  }
  pending_.reset();
  retry_timer_.stop();
}

void PathReception::refuse(const std::string& reason) {
  const nav_msgs::Path& msg = *pending_->msg;
  ++refused_;
  health_.rejected(ros::WallTime::now().toSec(), reason);
  const std::string kept = kept_();
  ROS_ERROR_STREAM("Refusing the path on " << topic_ << " from " << pending_->publisher << " ("
                                           << msg.poses.size() << " poses, frame '"
                                           << msg.header.frame_id << "'): " << reason << "; "
                                           << (kept.empty() ? "no path: the robot stays at rest"
                                                            : "keeping the " + kept));
  updater_->force_update();
}

void PathReception::report(diagnostic_updater::DiagnosticStatusWrapper& status, bool following) {
  using diagnostic_msgs::DiagnosticStatus;
  status.add(topic_ + " accepted", accepted_);
  status.add(topic_ + " refused", refused_);
  if (!health_.lastReason().empty()) status.add(topic_ + " last refusal", health_.lastReason());
  if (!following) {
    // At rest: with a refused path that is an error of the sender's, otherwise the wait for one.
    status.mergeSummary(refused_ > 0 ? DiagnosticStatus::ERROR : DiagnosticStatus::WARN,
                        refused_ > 0 ? "path refused, none to follow: " + health_.lastReason()
                                     : "waiting for a path on " + topic_);
    return;
  }
  const HealthLevel level = health_.level(ros::WallTime::now().toSec());
  if (level != HealthLevel::kOk) {
    status.mergeSummary(statusLevel(level), "path refused on " + topic_ +
                                                " (keeping the last good one): " + health_.lastReason());
  }
}

}  // namespace spherical_robots
