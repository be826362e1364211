#pragma once
// How a node's health follows the input it rejects, with time as a number (no ROS): WARN while
// rejections continue, ERROR while they come faster than a rate, and back to OK only once good
// input has flowed for a while after the last rejection. An operator's monitor then shows a
// robot under a burst of bad messages as unhealthy, not as OK with a counter moving.

#include <deque>
#include <string>

namespace spherical_robots {

enum class HealthLevel { kOk, kWarn, kError };

/// "OK", "WARN", "ERROR".
const char* toString(HealthLevel level);

struct InputHealthPolicy {
  double window = 1.0;       ///< [s] over which the rejection rate is counted, > 0
  double error_rate = 20.0;  ///< [1/s] rejections per second above which the level is ERROR, > 0
  double recovery = 2.0;     ///< [s] of good input after the last rejection before OK again, > 0
};

/// @throw std::invalid_argument naming the field that is not finite and > 0.
void validate(const InputHealthPolicy& policy);

class InputHealth {
 public:
  /// @throw std::invalid_argument as validate().
  explicit InputHealth(InputHealthPolicy policy = {});

  /// A message was accepted at t [s] (any monotonic clock; the nodes use wall time, which a
  /// stray /clock cannot move).
  void accepted(double t);
  /// A message was rejected at t [s] for `reason`.
  void rejected(double t, const std::string& reason);

  /// OK before any rejection and once good input has been accepted for `recovery` seconds after
  /// the last one (at least one message accepted in that time, and none rejected); ERROR while
  /// more than error_rate per second were rejected over the last window; WARN otherwise. A clock
  /// that went back past the last rejection forgets the history (a restarted clock).
  HealthLevel level(double t);
  /// Rejections per second over the last window before t [1/s].
  double rejectionRate(double t);
  const std::string& lastReason() const { return last_reason_; }
  const InputHealthPolicy& policy() const { return policy_; }

 private:
  void forgetBefore(double t);

  InputHealthPolicy policy_;
  std::deque<double> recent_rejections_;  ///< times within the window, oldest first
  bool rejected_ever_ = false;
  double last_rejection_ = 0.0;
  bool accepted_since_rejection_ = false;
  std::string last_reason_;
};

}  // namespace spherical_robots
