#pragma once
// Desired paths of the paper's section 6, given by their projection on the XY plane and lifted
// onto the terrain: p_d(t) = (x_d, y_d, f(x_d, y_d)).

#include <Eigen/Core>
#include <memory>
#include <string>

#include "spherical_robots/terrain/surface.hpp"

namespace spherical_robots::terrain {

/// Where a planar reference is at one time, and how fast it moves there.
struct PathPoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< (x_d, y_d) [m]
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  ///< (x_d', y_d') [m/s]
};

/// Which velocity of the reference a law wants: its mean over [t + lead - length/2,
/// t + lead + length/2] [s]; {0, 0} is p_d'(t) itself.
struct VelocityWindow {
  double lead = 0.0;    ///< [s] >= 0: how far ahead of t the window is centred
  double length = 0.0;  ///< [s] >= 0
};

/// A planar reference (x_d(t), y_d(t)) [m] and its velocity [m/s].
class ReferencePath {
 public:
  virtual ~ReferencePath() = default;
  /// Position and velocity together: they share their trigonometry, and the closed loop needs
  /// both at every new RK stage time. @throw std::invalid_argument on a non-finite t.
  virtual PathPoint at(double t) const = 0;
  Eigen::Vector2d position(double t) const { return at(t).position; }
  Eigen::Vector2d velocity(double t) const { return at(t).velocity; }
  /// The mean velocity [m/s] over [t - window/2, t + window/2], window [s] > 0: the chord
  /// (position(t + window/2) - position(t - window/2)) / window.
  virtual Eigen::Vector2d meanVelocity(double t, double window) const;
  /// The position at t with the velocity over window (a length of 0: at t + lead itself), as
  /// liftOntoSurface lifts them; the window is not checked. A path whose mean velocity comes
  /// from its state at one time overrides this to evaluate t once (the closed loop asks at every
  /// new RK stage time).
  virtual PathPoint windowedAt(double t, const VelocityWindow& window) const;
  /// The span [s] desired_path shows: one lap of a path that repeats (it repeats after that),
  /// the whole of one that ends.
  virtual double duration() const = 0;
  virtual std::string describe() const = 0;
};

/// x_d = r cos(w t), y_d = r sin(w t): the circle the paper's eq 60 means (it prints cos twice).
class CirclePath final : public ReferencePath {
 public:
  /// @param radius r [m] > 0, @param angular_rate w [rad/s] != 0. @throw std::invalid_argument
  CirclePath(double radius, double angular_rate);
  PathPoint at(double t) const override;
  /// Closed form: velocity(t) sin(w window/2) / (w window/2).
  Eigen::Vector2d meanVelocity(double t, double window) const override;
  PathPoint windowedAt(double t, const VelocityWindow& window) const override;
  double duration() const override;
  std::string describe() const override;

 private:
  /// sin(w window/2) / (w window/2): the mean velocity over window [s] > 0 over the velocity.
  double meanVelocityFactor(double window) const;

  double radius_;
  double angular_rate_;
};

/// The diamond (d,0) -> (0,d) -> (-d,0) -> (0,-d) -> (d,0), counter-clockwise from (d,0) at t = 0,
/// at a constant XY speed. At a vertex the velocity is that of the edge being entered.
class DiamondPath final : public ReferencePath {
 public:
  /// @param half_diagonal d [m] > 0, @param speed [m/s] > 0. @throw std::invalid_argument
  DiamondPath(double half_diagonal, double speed);
  PathPoint at(double t) const override;
  double duration() const override;
  std::string describe() const override;

 private:
  double half_diagonal_;
  double speed_;
};

/// A desired point on the terrain and its 3D velocity.
struct DesiredPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< p_d [m]
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< (x_d', y_d', f_x x_d' + f_y y_d') [m/s]
};

/// p_d(t) on the surface, with the path's velocity over window (ReferencePath::meanVelocity; by
/// default p_d'(t)) lifted onto the tangent plane at p_d(t): a law whose feed-forward must not
/// jump at a corner, or must lead a turn, asks for a window.
/// @throw std::invalid_argument on a non-finite t or a negative or non-finite window.
DesiredPoint liftOntoSurface(const ReferencePath& path, const Surface& surface, double t,
                             const VelocityWindow& window = {});

}  // namespace spherical_robots::terrain
