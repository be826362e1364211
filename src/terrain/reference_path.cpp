#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/core/validation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spherical_robots::terrain {
namespace {

void requireFiniteTime(double t) { requireFinite(t, "reference path: time [s]"); }

}  // namespace

CirclePath::CirclePath(double radius, double angular_rate)
    : radius_(radius), angular_rate_(angular_rate) {
  requirePositive(radius, "circle path: radius [m]");
  if (!std::isfinite(angular_rate) || angular_rate == 0.0) {
    throw std::invalid_argument("circle path: angular_rate must be finite and non-zero, got " +
                                std::to_string(angular_rate));
  }
}

// Eq 60 corrected: the printed y = 2 cos(0.05 t) would make the path a line.
PathPoint CirclePath::at(double t) const {
  requireFiniteTime(t);
  const auto [sin_wt, cos_wt] = sinCos(angular_rate_ * t);
  PathPoint point;
  point.position = radius_ * Eigen::Vector2d(cos_wt, sin_wt);
  point.velocity = radius_ * angular_rate_ * Eigen::Vector2d(-sin_wt, cos_wt);
  return point;
}

double CirclePath::meanVelocityFactor(double window) const {
  const double half_turn = 0.5 * angular_rate_ * window;
  return std::sin(half_turn) / half_turn;
}

Eigen::Vector2d CirclePath::meanVelocity(double t, double window) const {
  requirePositive(window, "circle path: mean velocity window [s]");
  return at(t).velocity * meanVelocityFactor(window);
}

// One sincos for a window centred on t (the smooth law's for 3R and 2R), not one for the
// position and one for the mean velocity.
PathPoint CirclePath::windowedAt(double t, const VelocityWindow& window) const {
  PathPoint point = at(t);
  if (window.lead > 0.0) point.velocity = at(t + window.lead).velocity;
  if (window.length > 0.0) point.velocity *= meanVelocityFactor(window.length);
  return point;
}

double CirclePath::duration() const { return 2.0 * M_PI / std::abs(angular_rate_); }

std::string CirclePath::describe() const {
  std::ostringstream text;
  text << "circle r=" << radius_ << " m w=" << angular_rate_ << " rad/s";
  return text.str();
}

DiamondPath::DiamondPath(double half_diagonal, double speed)
    : half_diagonal_(half_diagonal), speed_(speed) {
  requirePositive(half_diagonal, "diamond path: half_diagonal [m]");
  requirePositive(speed, "diamond path: speed [m/s]");
}

namespace {

struct DiamondEdge {
  Eigen::Vector2d start;
  Eigen::Vector2d direction;  // unit
  double travelled;           // along this edge [m]
};

DiamondEdge diamondEdge(double half_diagonal, double speed, double t) {
  requireFiniteTime(t);
  const std::array<Eigen::Vector2d, 4> vertices = {
      Eigen::Vector2d(half_diagonal, 0.0), Eigen::Vector2d(0.0, half_diagonal),
      Eigen::Vector2d(-half_diagonal, 0.0), Eigen::Vector2d(0.0, -half_diagonal)};
  const double edge_length = std::sqrt(2.0) * half_diagonal;
  double along = std::fmod(speed * t, 4.0 * edge_length);
  if (along < 0.0) along += 4.0 * edge_length;
  const int edge = std::min(3, static_cast<int>(along / edge_length));
  const Eigen::Vector2d& start = vertices[edge];
  const Eigen::Vector2d& end = vertices[(edge + 1) % 4];
  return {start, (end - start) / edge_length, along - edge * edge_length};
}

}  // namespace

PathPoint DiamondPath::at(double t) const {
  const DiamondEdge edge = diamondEdge(half_diagonal_, speed_, t);
  PathPoint point;
  point.position = edge.start + edge.travelled * edge.direction;
  point.velocity = speed_ * edge.direction;
  return point;
}

double DiamondPath::duration() const { return 4.0 * std::sqrt(2.0) * half_diagonal_ / speed_; }

std::string DiamondPath::describe() const {
  std::ostringstream text;
  text << "diamond d=" << half_diagonal_ << " m v=" << speed_ << " m/s";
  return text.str();
}

Eigen::Vector2d ReferencePath::meanVelocity(double t, double window) const {
  requirePositive(window, "reference path: mean velocity window [s]");
  return (position(t + 0.5 * window) - position(t - 0.5 * window)) / window;
}

PathPoint ReferencePath::windowedAt(double t, const VelocityWindow& window) const {
  PathPoint point = at(t);
  if (window.length > 0.0) {
    point.velocity = meanVelocity(t + window.lead, window.length);
  } else if (window.lead > 0.0) {
    point.velocity = velocity(t + window.lead);
  }
  return point;
}

DesiredPoint liftOntoSurface(const ReferencePath& path, const Surface& surface, double t,
                             const VelocityWindow& window) {
  if (!std::isfinite(window.lead) || window.lead < 0.0) {
    rejectNumber(window.lead, "reference path: velocity window lead [s]", "finite and >= 0");
  }
  if (!std::isfinite(window.length) || window.length < 0.0) {
    rejectNumber(window.length, "reference path: velocity window length [s]", "finite and >= 0");
  }
  const PathPoint planar = path.windowedAt(t, window);
  const Eigen::Vector2d& xy = planar.position;
  const Eigen::Vector2d& xy_rate = planar.velocity;
  const SurfacePoint ground = surface.evaluate(xy.x(), xy.y());
  DesiredPoint desired;
  desired.position = {xy.x(), xy.y(), ground.height};
  desired.velocity = {xy_rate.x(), xy_rate.y(), ground.gradient.dot(xy_rate)};
  return desired;
}

}  // namespace spherical_robots::terrain
