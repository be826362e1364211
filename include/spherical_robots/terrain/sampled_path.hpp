#pragma once
// A reference path through sampled points, the user's own: a CSV file (sphere_sim terrain
// --path-file) or a nav_msgs/Path the pursuit controller receives. The points are interpolated
// by a cubic spline in time, one per coordinate: C2, so the velocity the laws feed forward (and
// the smooth law's mean over a window) is continuous, with position error O(h^4) and velocity
// error O(h^3) for point spacing h in time (docs/conventions.md, "Sampled paths").

#include <boost/math/interpolators/cubic_hermite.hpp>

#include <Eigen/Core>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/terrain/reference_path.hpp"

namespace spherical_robots::terrain {

/// A point of a path and its time.
struct TimedPoint {
  double t = 0.0;                                      ///< [s]
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< (x, y) [m]
};

/// A point as a nav_msgs/Path pose carries it: its stamp and position.
struct StampedPoint {
  Nanoseconds stamp = 0;                               ///< [ns], as ros::Time
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< (x, y) [m]
};

/// A bad point of a path: what() names its index and value; index() lets a reader of a file name
/// the line.
class InvalidPathPoint : public std::invalid_argument {
 public:
  InvalidPathPoint(std::size_t index, const std::string& problem);
  std::size_t index() const { return index_; }

 private:
  std::size_t index_;
};

/// The cubic spline through timed points. Closed if its last point is its first (within
/// kClosingDistance): then the spline is periodic (C2 across the seam too) and the path repeats
/// with period duration(), before its start as after its end. Open otherwise: before its first
/// time it holds the first point and after its last time the last one, with velocity zero.
/// Open ends are not-a-knot (no end slopes or curvatures to invent; O(h^4) up to the ends); two
/// points make a line and three a parabola.
class SampledPath final : public ReferencePath {
 public:
  /// [m] a last point this close to the first closes the path.
  static constexpr double kClosingDistance = 1e-6;

  /// Through `points` at their times; the path's t = 0 is the first point's time.
  /// @throw std::invalid_argument with fewer than 2 points; InvalidPathPoint for a time or
  /// coordinate that is not finite or a time not after the one before.
  static SampledPath timed(const std::vector<TimedPoint>& points);

  /// Through untimed `points` at `speed` [m/s] > 0: each point's time is the length of the
  /// polyline up to it over speed. A point equal to the one before is skipped (planners repeat
  /// their goal). @throw InvalidPathPoint for a coordinate that is not finite;
  /// std::invalid_argument for a bad speed or fewer than 2 distinct points; InvalidPathPoint for
  /// a point whose time along the path a double cannot tell from the one before's (a coordinate
  /// far off) or is not finite.
  static SampledPath atSpeed(const std::vector<Eigen::Vector2d>& points, double speed);

  /// A path as nav_msgs/Path carries it: strictly increasing stamps are a timed path, times
  /// relative to the first stamp; stamps all equal (all zero, as move_base and most planners
  /// publish them) an untimed one, at untimed_speed [m/s]. @throw InvalidPathPoint naming the
  /// first stamp that is neither, or as timed and atSpeed.
  static SampledPath fromStamped(const std::vector<StampedPoint>& points, double untimed_speed);

  PathPoint at(double t) const override;
  double duration() const override { return times_.back(); }
  std::string describe() const override;
  bool closed() const { return closed_; }
  std::size_t size() const { return times_.size(); }

 private:
  using Spline = boost::math::interpolators::cubic_hermite<std::vector<double>>;
  SampledPath(std::vector<double> times, bool closed, Spline x, Spline y);
  /// Through checked points at times from 0, strictly increasing.
  static SampledPath build(std::vector<double> times, std::vector<Eigen::Vector2d> positions);

  std::vector<double> times_;  ///< [s] from 0
  bool closed_;
  Spline x_;
  Spline y_;
};

}  // namespace spherical_robots::terrain
