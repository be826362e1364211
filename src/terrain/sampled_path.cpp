#include "spherical_robots/terrain/sampled_path.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::terrain {
namespace {

using Values = Eigen::Matrix<double, Eigen::Dynamic, 2>;  // one row per point: x, y

// Enough digits that two times that differ print differently.
constexpr int kMessagePrecision = 15;

[[noreturn]] void rejectPoint(std::size_t index, const std::string& problem) {
  throw InvalidPathPoint(index, problem);
}

void requireFinitePosition(std::size_t index, const Eigen::Vector2d& position) {
  for (int axis = 0; axis < 2; ++axis) {
    if (!std::isfinite(position[axis])) {
      std::ostringstream problem;
      problem << (axis == 0 ? "x" : "y") << " [m] must be finite, got " << position[axis];
      rejectPoint(index, problem.str());
    }
  }
}

void requireTwoPoints(std::size_t count, const char* kind) {
  if (count < 2) {
    throw std::invalid_argument(std::string("a path needs at least 2 ") + kind + "points, got " +
                                std::to_string(count));
  }
}

Values solve(Eigen::Index unknowns, const std::vector<Eigen::Triplet<double>>& entries,
             const Values& right) {
  Eigen::SparseMatrix<double> matrix(unknowns, unknowns);
  matrix.setFromTriplets(entries.begin(), entries.end());  // sums repeated entries
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(matrix);
  if (lu.info() != Eigen::Success) {
    throw std::logic_error("sampled path: the spline's system is singular: " + lu.lastErrorMessage());
  }
  return lu.solve(right);
}

// The spline's first derivatives at the points: the second derivative continuous at every
// interior point (and, periodic, at the seam), in the slope form of de Boor, "A Practical Guide
// to Splines", ch. IV (as MATLAB's spline writes it):
//   h_i m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_{i-1} m_{i+1} = 3 (h_i d_{i-1} + h_{i-1} d_i),
// h_i the intervals, d_i the chords' slopes. Open ends are not-a-knot (the third derivative
// continuous at the second and the last but one point). Sparse: O(n) for n points.
Values splineSlopes(const std::vector<double>& t, const Values& v, bool periodic) {
  const Eigen::Index n = v.rows();
  const Eigen::Index intervals = n - 1;
  Eigen::VectorXd h(intervals);
  Values d(intervals, 2);
  for (Eigen::Index i = 0; i < intervals; ++i) {
    h(i) = t[i + 1] - t[i];
    d.row(i) = (v.row(i + 1) - v.row(i)) / h(i);
  }
  Values slopes(n, 2);
  std::vector<Eigen::Triplet<double>> entries;
  if (periodic) {
    // Unknowns m_0 .. m_{n-2}; m_{n-1} = m_0, the last point being the first.
    Values right(intervals, 2);
    for (Eigen::Index i = 0; i < intervals; ++i) {
      const Eigen::Index before = (i + intervals - 1) % intervals;
      const Eigen::Index after = (i + 1) % intervals;
      entries.emplace_back(i, before, h(i));
      entries.emplace_back(i, i, 2.0 * (h(before) + h(i)));
      entries.emplace_back(i, after, h(before));
      right.row(i) = 3.0 * (h(i) * d.row(before) + h(before) * d.row(i));
    }
    slopes.topRows(intervals) = solve(intervals, entries, right);
    slopes.row(n - 1) = slopes.row(0);
    return slopes;
  }
  if (n == 2) {  // the line
    slopes.row(0) = slopes.row(1) = d.row(0);
    return slopes;
  }
  if (n == 3) {  // the parabola: not-a-knot's two conditions fall on the one interior point
    const Eigen::RowVector2d curvature = (d.row(1) - d.row(0)) / (h(0) + h(1));
    slopes.row(0) = d.row(0) - h(0) * curvature;
    slopes.row(1) = d.row(0) + h(0) * curvature;
    slopes.row(2) = d.row(1) + h(1) * curvature;
    return slopes;
  }
  Values right(n, 2);
  const double first_span = h(0) + h(1);
  entries.emplace_back(0, 0, h(1));
  entries.emplace_back(0, 1, first_span);
  right.row(0) = ((h(0) + 2.0 * first_span) * h(1) * d.row(0) + h(0) * h(0) * d.row(1)) / first_span;
  for (Eigen::Index i = 1; i < n - 1; ++i) {
    entries.emplace_back(i, i - 1, h(i));
    entries.emplace_back(i, i, 2.0 * (h(i - 1) + h(i)));
    entries.emplace_back(i, i + 1, h(i - 1));
    right.row(i) = 3.0 * (h(i) * d.row(i - 1) + h(i - 1) * d.row(i));
  }
  const double last = h(n - 2);
  const double before_last = h(n - 3);
  const double last_span = before_last + last;
  entries.emplace_back(n - 1, n - 2, last_span);
  entries.emplace_back(n - 1, n - 1, before_last);
  right.row(n - 1) =
      (last * last * d.row(n - 3) + (2.0 * last_span + last) * before_last * d.row(n - 2)) / last_span;
  return solve(n, entries, right);
}

}  // namespace

InvalidPathPoint::InvalidPathPoint(std::size_t index, const std::string& problem)
    : std::invalid_argument("path point " + std::to_string(index) + ": " + problem),
      index_(index) {}

SampledPath::SampledPath(std::vector<double> times, bool closed, Spline x, Spline y)
    : times_(std::move(times)), closed_(closed), x_(std::move(x)), y_(std::move(y)) {}

SampledPath SampledPath::timed(const std::vector<TimedPoint>& points) {
  requireTwoPoints(points.size(), "");
  std::vector<double> times;
  std::vector<Eigen::Vector2d> positions;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const TimedPoint& point = points[i];
    if (!std::isfinite(point.t)) {
      std::ostringstream problem;
      problem << "t [s] must be finite, got " << point.t;
      rejectPoint(i, problem.str());
    }
    if (i > 0 && !(point.t > points[i - 1].t)) {
      std::ostringstream problem;
      problem.precision(kMessagePrecision);
      problem << "t [s] must be after point " << i - 1 << "'s " << points[i - 1].t << ", got "
              << point.t;
      rejectPoint(i, problem.str());
    }
    requireFinitePosition(i, point.position);
    times.push_back(point.t - points.front().t);
    positions.push_back(point.position);
  }
  return build(std::move(times), std::move(positions));
}

SampledPath SampledPath::atSpeed(const std::vector<Eigen::Vector2d>& points, double speed) {
  requirePositive(speed, "untimed path: speed [m/s]");
  std::vector<double> times;
  std::vector<Eigen::Vector2d> kept;
  for (std::size_t i = 0; i < points.size(); ++i) {
    requireFinitePosition(i, points[i]);
    if (!kept.empty() && points[i] == kept.back()) continue;
    if (kept.empty()) {
      times.push_back(0.0);
    } else {
      // A step too short for the time so far (after a huge one), or a time beyond a double's
      // range, would give the spline equal or infinite times.
      const double step = (points[i] - kept.back()).norm() / speed;
      const double time = times.back() + step;
      if (!(time > times.back()) || !std::isfinite(time)) {
        std::ostringstream problem;
        problem.precision(kMessagePrecision);
        problem << "its time along the path, " << times.back() << " s + " << step << " s (at "
                << speed << " m/s), is not a finite time after the point before's in double "
                << "precision: a coordinate of this point or an earlier one is far off";
        rejectPoint(i, problem.str());
      }
      times.push_back(time);
    }
    kept.push_back(points[i]);
  }
  requireTwoPoints(kept.size(), "distinct ");
  return build(std::move(times), std::move(kept));
}

SampledPath SampledPath::fromStamped(const std::vector<StampedPoint>& points,
                                     double untimed_speed) {
  requireTwoPoints(points.size(), "");
  bool untimed = true;
  for (const StampedPoint& point : points) untimed = untimed && point.stamp == points.front().stamp;
  if (untimed) {
    std::vector<Eigen::Vector2d> positions;
    for (const StampedPoint& point : points) positions.push_back(point.position);
    return atSpeed(positions, untimed_speed);
  }
  std::vector<TimedPoint> timed;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0 && points[i].stamp <= points[i - 1].stamp) {
      std::ostringstream problem;
      problem.precision(kMessagePrecision);
      problem << "stamp " << stampSeconds(points[i].stamp) << " s is not after point " << i - 1
              << "'s " << stampSeconds(points[i - 1].stamp)
              << " s: stamps must all increase (a timed path) or all be equal (an untimed one)";
      rejectPoint(i, problem.str());
    }
    timed.push_back({stampSeconds(points[i].stamp - points.front().stamp), points[i].position});
  }
  return SampledPath::timed(timed);
}

SampledPath SampledPath::build(std::vector<double> times, std::vector<Eigen::Vector2d> positions) {
  const std::size_t n = positions.size();
  const bool closed = (positions.back() - positions.front()).norm() <= kClosingDistance;
  if (closed) positions.back() = positions.front();  // the periodic spline's seam, exactly
  Values values(n, 2);
  for (std::size_t i = 0; i < n; ++i) values.row(i) = positions[i].transpose();
  const Values slopes = splineSlopes(times, values, closed);
  const auto column = [n](const Values& matrix, int axis) {
    std::vector<double> entries(n);
    for (std::size_t i = 0; i < n; ++i) entries[i] = matrix(i, axis);
    return entries;
  };
  Spline x(std::vector<double>(times), column(values, 0), column(slopes, 0));
  Spline y(std::vector<double>(times), column(values, 1), column(slopes, 1));
  return SampledPath(std::move(times), closed, std::move(x), std::move(y));
}

PathPoint SampledPath::at(double t) const {
  requireFinite(t, "sampled path: time [s]");
  const double end = times_.back();
  PathPoint point;
  if (!closed_ && (t < 0.0 || t > end)) {  // held at its start or end
    const double held = t < 0.0 ? 0.0 : end;
    point.position = {x_(held), y_(held)};
    return point;
  }
  double s = closed_ ? std::fmod(t, end) : t;
  if (s < 0.0) s = std::min(s + end, end);
  point.position = {x_(s), y_(s)};
  point.velocity = {x_.prime(s), y_.prime(s)};
  return point;
}

std::string SampledPath::describe() const {
  std::ostringstream text;
  text << "sampled path of " << times_.size() << " points over " << times_.back() << " s, "
       << (closed_ ? "closed (repeats)" : "open (holds its end)");
  return text.str();
}

}  // namespace spherical_robots::terrain
