#include "spherical_robots/rotor/motion_planner.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <boost/math/interpolators/makima.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/geometric_phase.hpp"

namespace spherical_robots::rotor {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr int kUniformNodes = 64;      // leaf table nodes uniform in the geodesic radius
constexpr int kEquatorNodes = 64;      // … and uniform in log(cos 2α), dense where eq 30 stiffens
constexpr double kTableTolerance = 1e-7;   // the table only starts Newton: a looser integration
constexpr double kMaxTurnPerCell = 0.5;    // largest holonomy change between table nodes [rad]
constexpr double kMaxShiftPerCell = 0.25;  // largest shift change between table nodes [R]
constexpr double kMinCellWidth = 1e-6;     // table intervals are not bisected below this [R]
constexpr int kRefinePasses = 6;
constexpr double kFiniteStep = 1e-7;   // forward-difference step of Newton's Jacobian [R]
constexpr double kResidualTolerance = 1e-11;  // residual of eqs 32-33 that ends Newton
constexpr double kConvergedStep = 1e-10;      // … or a step this small [R]
constexpr double kConvergedResidual = 1e-8;   // … with a residual below this
constexpr int kNewtonIterations = 30;
constexpr double kDuplicate = 1e-7;    // two roots closer than this in (a, b) are one [R]
constexpr double kAcceptedError = 1e-6;  // largest final_error of a reported plan
constexpr double kZeroShift = 1e-12;   // h_des below this is a pure turn [R]
// Smallest circle of a plan [R]: the null manoeuvre a, b -> 0 solves a pure turn's equations to
// within the tolerances (a leaf's shift is ~2π a³), so tinier circles are not plans.
constexpr double kMinRadius = 0.01;

/// The leaf table: radii (the first is 0, the limit where a leaf does nothing), their phases,
/// and a smooth interpolant of them (modified Akima) that gives Newton its start and Jacobian.
struct LeafTable {
  using Spline = boost::math::interpolators::makima<std::vector<double>>;

  std::vector<double> radius;
  std::vector<LeafPhase> leaf;
  std::vector<Spline> splines;  // shift x, shift y, holonomy over radius

  LeafPhase interpolate(double r) const {
    return {Eigen::Vector2d(splines[0](r), splines[1](r)), splines[2](r)};
  }
};

LeafTable tabulateLeaves(double k, double max_radius) {
  const double alpha_max = std::asin(max_radius);
  const double log_q_max = std::log(std::cos(2.0 * alpha_max));
  std::vector<double> alphas;
  for (int i = 1; i <= kUniformNodes; ++i) alphas.push_back(alpha_max * i / kUniformNodes);
  for (int i = 1; i < kEquatorNodes; ++i) {
    alphas.push_back(0.5 * std::acos(std::exp(log_q_max * i / kEquatorNodes)));
  }
  std::sort(alphas.begin(), alphas.end());
  std::vector<double> radius{0.0};
  for (double alpha : alphas) {
    const double r = std::min(std::sin(alpha), max_radius);
    if (r - radius.back() >= 1e-9) radius.push_back(r);
  }
  const auto leaf = [k](double r) {
    return r > 0.0 ? leafPhase(k, r, kTableTolerance) : LeafPhase{};
  };
  std::vector<LeafPhase> leaves;
  for (double r : radius) leaves.push_back(leaf(r));
  // Bisect every interval over which a leaf's holonomy or shift changes too much for the
  // interpolant (and the sign tests) to follow: near the equator they turn fast for large k.
  LeafTable table;
  for (int pass = 0; pass < kRefinePasses; ++pass) {
    table.radius = {radius.front()};
    table.leaf = {leaves.front()};
    for (std::size_t i = 1; i < radius.size(); ++i) {
      const bool coarse =
          std::abs(leaves[i].holonomy - leaves[i - 1].holonomy) > kMaxTurnPerCell ||
          (leaves[i].shift - leaves[i - 1].shift).norm() > kMaxShiftPerCell;
      if (coarse && radius[i] - radius[i - 1] > kMinCellWidth) {
        const double middle = 0.5 * (radius[i] + radius[i - 1]);
        table.radius.push_back(middle);
        table.leaf.push_back(leaf(middle));
      }
      table.radius.push_back(radius[i]);
      table.leaf.push_back(leaves[i]);
    }
    const bool refined = table.radius.size() > radius.size();
    radius = table.radius;
    leaves = table.leaf;
    if (!refined) break;
  }
  for (int component = 0; component < 3; ++component) {
    std::vector<double> values;
    for (const LeafPhase& leaf : table.leaf) {
      values.push_back(component < 2 ? leaf.shift[component] : leaf.holonomy);
    }
    table.splines.emplace_back(std::vector<double>(table.radius), std::move(values));
  }
  return table;
}

/// η(a, b) and h(a, b) at every pair of table radii (composeLeaves, with each first leaf's
/// rotation computed once), and their ranges for the reason of an empty plan.
struct PhaseGrid {
  std::size_t n = 0;
  std::vector<double> eta;  // [i * n + j]: a = radius[i], b = radius[j]
  std::vector<double> h;
  double eta_lo = 0.0, eta_hi = 0.0, h_hi = 0.0;

  explicit PhaseGrid(const LeafTable& table) : n(table.radius.size()), eta(n * n), h(n * n) {
    for (std::size_t i = 0; i < n; ++i) {
      const LeafPhase& first = table.leaf[i];
      const auto [s, c] = sinCos(first.holonomy);
      for (std::size_t j = 0; j < n; ++j) {
        const LeafPhase& second = table.leaf[j];
        // shift = s(a) + Rot(−η(a)) diag(1, −1) s(b), as composeLeaves.
        const double x = second.shift.x(), y = -second.shift.y();
        eta[i * n + j] = first.holonomy - second.holonomy;
        // |shift| by sqrt, not hypot: shifts of at most a few R neither overflow nor underflow.
        const double u = first.shift.x() + c * x + s * y, v = first.shift.y() - s * x + c * y;
        h[i * n + j] = std::sqrt(u * u + v * v);
      }
    }
    eta_lo = *std::min_element(eta.begin(), eta.end());
    eta_hi = *std::max_element(eta.begin(), eta.end());
    h_hi = *std::max_element(h.begin(), h.end());
  }
};

/// The equations a plan solves: η(a, b) = η_des (eq 32) and h(a, b) = h_req (eq 33), or, for a
/// pure turn (h_req = 0), η = η_des and shift = 0.
struct Equations {
  double eta = 0.0;
  double h = 0.0;
  bool pure_turn = false;

  Eigen::VectorXd residual(const StepPhase& phase) const {
    if (pure_turn) return Eigen::Vector3d(phase.eta - eta, phase.shift.x(), phase.shift.y());
    return Eigen::Vector2d(phase.eta - eta, phase.h - h);
  }
};

/// Residual and forward-difference Jacobian of the equations for leaves given by `leaf(r)`.
template <typename Leaf>
Eigen::MatrixXd jacobian(const Equations& equations, const Leaf& leaf, const Eigen::Vector2d& x,
                         const LeafPhase& at_a, const LeafPhase& at_b, const Eigen::VectorXd& f,
                         double max_radius) {
  Eigen::MatrixXd out(f.size(), 2);
  for (int j = 0; j < 2; ++j) {
    // Step inwards at the upper limit so the probe stays in the domain.
    const double step = x[j] + kFiniteStep < max_radius ? kFiniteStep : -kFiniteStep;
    const LeafPhase moved = leaf(x[j] + step);
    const StepPhase phase = j == 0 ? composeLeaves(moved, at_b) : composeLeaves(at_a, moved);
    out.col(j) = (equations.residual(phase) - f) / step;
  }
  return out;
}

/// Newton's method on the interpolated leaves from a table cell: the interpolant's root, if it
/// converges inside [kMinRadius, max_radius]^2.
std::optional<Eigen::Vector2d> modelRoot(const Equations& equations, const LeafTable& table,
                                         Eigen::Vector2d x, double max_radius) {
  const auto model = [&table](double r) { return table.interpolate(r); };
  for (int iteration = 0; iteration < kNewtonIterations; ++iteration) {
    const LeafPhase at_a = model(x.x()), at_b = model(x.y());
    const Eigen::VectorXd f = equations.residual(composeLeaves(at_a, at_b));
    const Eigen::Vector2d delta =
        jacobian(equations, model, x, at_a, at_b, f, max_radius).colPivHouseholderQr().solve(-f);
    x += delta;
    if (!x.allFinite() || x.minCoeff() < kMinRadius || x.maxCoeff() > max_radius) {
      return std::nullopt;
    }
    if (delta.cwiseAbs().maxCoeff() < 1e-13) return x;
  }
  return std::nullopt;
}

/// A root of the equations and the step phase of its integrated leaves.
struct Root {
  Eigen::Vector2d radii;  // (a, b) [R]
  StepPhase phase;        // stepPhase(k, a, b), kept from the iteration that found the root
};

/// Quasi-Newton iteration on integrated leaves from the interpolant's root, starting from the
/// interpolant's Jacobian and updating it by Broyden's rule (one pair of leaf integrations per
/// iteration) or, if `differences`, recomputing it by forward differences of integrated leaves
/// (two pairs). Converged when the step is below kConvergedStep (integration noise, up to ~1e-8
/// near the equator, keeps the residual from reaching zero) and the residual below
/// kConvergedResidual.
std::optional<Root> polish(double k, const Equations& equations, const LeafTable& table,
                           Eigen::Vector2d x, double max_radius, bool differences) {
  const auto model = [&table](double r) { return table.interpolate(r); };
  const auto integrated = [k](double r) { return leafPhase(k, r); };
  LeafPhase at_a = model(x.x()), at_b = model(x.y());
  Eigen::MatrixXd j = jacobian(equations, model, x, at_a, at_b,
                               equations.residual(composeLeaves(at_a, at_b)), max_radius);
  at_a = integrated(x.x());
  at_b = integrated(x.y());
  Eigen::VectorXd f = equations.residual(composeLeaves(at_a, at_b));
  for (int iteration = 0; iteration < kNewtonIterations; ++iteration) {
    if (f.cwiseAbs().maxCoeff() < kResidualTolerance) return Root{x, composeLeaves(at_a, at_b)};
    if (differences && iteration > 0) {
      j = jacobian(equations, integrated, x, at_a, at_b, f, max_radius);
    }
    const Eigen::Vector2d delta = j.colPivHouseholderQr().solve(-f);
    x += delta;
    if (!x.allFinite() || x.minCoeff() < kMinRadius || x.maxCoeff() > max_radius) {
      return std::nullopt;
    }
    at_a = integrated(x.x());
    at_b = integrated(x.y());
    const Eigen::VectorXd next = equations.residual(composeLeaves(at_a, at_b));
    if (delta.cwiseAbs().maxCoeff() < kConvergedStep) {
      if (next.cwiseAbs().maxCoeff() < kConvergedResidual) {
        return Root{x, composeLeaves(at_a, at_b)};
      }
      return std::nullopt;
    }
    if (!differences) j += (next - f - j * delta) * delta.transpose() / delta.squaredNorm();
    f = next;
  }
  return std::nullopt;
}

bool changesSign(double a, double b, double c, double d) {
  const double lo = std::min({a, b, c, d}), hi = std::max({a, b, c, d});
  return lo <= 0.0 && hi >= 0.0;
}

/// Every root of the equations in the table's cells, refined and deduplicated.
std::vector<Root> roots(double k, const Equations& equations, const LeafTable& table,
                        const PhaseGrid& grid, double max_radius) {
  const std::size_t n = grid.n;
  const auto f = [&](std::size_t i, std::size_t j) { return grid.eta[i * n + j] - equations.eta; };
  const auto g = [&](std::size_t i, std::size_t j) { return grid.h[i * n + j] - equations.h; };
  std::vector<Root> found;
  std::vector<Eigen::Vector2d> guesses;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    for (std::size_t j = 0; j + 1 < n; ++j) {
      if (!changesSign(f(i, j), f(i + 1, j), f(i, j + 1), f(i + 1, j + 1))) continue;
      bool candidate;
      if (equations.pure_turn) {
        // h >= 0 touches zero instead of crossing it: accept cells where h is small compared
        // with its variation across the cell.
        const double lo = std::min({grid.h[i * n + j], grid.h[(i + 1) * n + j],
                                    grid.h[i * n + j + 1], grid.h[(i + 1) * n + j + 1]});
        const double spread = std::abs(g(i + 1, j + 1) - g(i, j)) +
                              std::abs(g(i + 1, j) - g(i, j + 1));
        candidate = lo <= spread;
      } else {
        candidate = changesSign(g(i, j), g(i + 1, j), g(i, j + 1), g(i + 1, j + 1));
      }
      if (!candidate) continue;
      const Eigen::Vector2d start(0.5 * (table.radius[i] + table.radius[i + 1]),
                                  0.5 * (table.radius[j] + table.radius[j + 1]));
      // Neighbouring cells of one root find the same interpolated root: polish it once.
      const std::optional<Eigen::Vector2d> guess = modelRoot(equations, table, start, max_radius);
      if (!guess) continue;
      const auto near = [](const Eigen::Vector2d& x, const Eigen::Vector2d& y) {
        return (x - y).cwiseAbs().maxCoeff() < kDuplicate;
      };
      if (std::any_of(guesses.begin(), guesses.end(),
                      [&](const Eigen::Vector2d& x) { return near(x, *guess); })) {
        continue;
      }
      guesses.push_back(*guess);
      std::optional<Root> root = polish(k, equations, table, *guess, max_radius, false);
      if (!root) root = polish(k, equations, table, *guess, max_radius, true);
      if (!root) continue;
      if (std::none_of(found.begin(), found.end(),
                       [&](const Root& x) { return near(x.radii, root->radii); })) {
        found.push_back(*root);
      }
    }
  }
  return found;
}

/// |sin(η/2) / sin(nη/2)| of eq 33 (corrected), its limit 1/n where both vanish, or nothing
/// where only the denominator does (the n shifts close into a polygon).
std::optional<double> shiftRatio(double eta, int steps) {
  if (steps == 1) return 1.0;
  const double one = std::sin(0.5 * eta), all = std::sin(0.5 * steps * eta);
  if (std::abs(all) > 1e-12) return std::abs(one / all);
  if (std::abs(one) <= 1e-12) return 1.0 / steps;  // ηn/2 and η/2 both multiples of π
  return std::nullopt;
}


/// Plans for one accumulated target heading ψ; appends a reason when there is no plan.
std::vector<RotorPlan> planHeading(const PlanRequest& request, double psi, const LeafTable& table,
                                   const PhaseGrid& grid, std::vector<std::string>& reasons) {
  const int n = request.steps;
  const double h_des = std::hypot(request.u_a, request.v_a);
  std::ostringstream why;
  why << "psi = " << psi << ": ";
  Equations equations;
  equations.eta = psi / n;  // eq 32
  const std::optional<double> ratio = shiftRatio(equations.eta, n);
  if (!ratio) {
    if (h_des > kZeroShift) {
      why << "with eta = psi/n = " << equations.eta << " the " << n
          << " step shifts close into a polygon (sin(n eta/2) = 0), so no plan reaches a "
             "target away from the start";
    } else {
      why << "with eta = psi/n = " << equations.eta << " every figure eight of holonomy eta "
          << "returns to the start after " << n
          << " steps: a continuum of plans, not enumerated; choose another n";
    }
    reasons.push_back(why.str());
    return {};
  }
  equations.h = *ratio * h_des;  // eq 33
  equations.pure_turn = h_des <= kZeroShift;

  std::vector<RotorPlan> plans;
  int rejected = 0;
  for (const Root& found : roots(request.k, equations, table, grid, request.max_radius)) {
    const Eigen::Vector2d& root = found.radii;
    const StepPhase& phase = found.phase;
    // Total shift for γ = 0: step j's shift turned by −jη (eqs 28-29); γ turns it by +γ.
    Eigen::Vector2d total = Eigen::Vector2d::Zero();
    for (int j = 0; j < n; ++j) total += Eigen::Rotation2Dd(-j * phase.eta) * phase.shift;
    const double gamma =
        equations.pure_turn
            ? 0.0
            : std::remainder(std::atan2(request.v_a, request.u_a) - std::atan2(total.y(), total.x()),
                             kTwoPi);
    const FigureEight curve(root.x(), root.y(), gamma);
    const PlaneState reached = integrateSteps(request.k, curve, n);
    RotorPlan plan;
    plan.a = root.x();
    plan.b = root.y();
    plan.gamma = gamma;
    plan.psi = psi;
    plan.length = n * curve.length();
    plan.final_error = std::max({std::abs(reached.u_a - request.u_a),
                                 std::abs(reached.v_a - request.v_a), std::abs(reached.psi - psi)});
    if (plan.final_error <= kAcceptedError) {
      plans.push_back(plan);
    } else {
      ++rejected;
    }
  }
  if (plans.empty()) {
    why << "no figure eight with radii " << kMinRadius << " R <= a, b <= " << request.max_radius
        << " R has eta = psi/n = " << equations.eta << " and h = " << equations.h
        << " R (k = " << request.k
        << "; over that range eta spans about [" << grid.eta_lo << ", " << grid.eta_hi
        << "] and h reaches about " << grid.h_hi << " R)";
    if (equations.pure_turn) {
      why << "; a pure turn needs zero shift and eta = psi/n, three equations for the two radii, "
             "which have no common solution in general";
    }
    if (rejected > 0) why << "; " << rejected << " root(s) failed verification";
    reasons.push_back(why.str());
  }
  return plans;
}

}  // namespace

void requireValid(const PlanRequest& request) {
  requireFinite(request.k, "inertia ratio k");
  if (request.k < 0.0) {
    std::ostringstream message;
    message << "inertia ratio k must be >= 0, got " << request.k;
    throw std::invalid_argument(message.str());
  }
  if (request.steps < 1 || request.steps > kMaxSteps) {
    throw std::invalid_argument("number of steps n must be in [1, " + std::to_string(kMaxSteps) +
                                "], got " + std::to_string(request.steps));
  }
  requireMagnitudeAtMost(request.k, kMaxInertiaRatio, "inertia ratio k");
  requireMagnitudeAtMost(request.u_a, kMaxTargetDistance, "target u_a [R]");
  requireMagnitudeAtMost(request.v_a, kMaxTargetDistance, "target v_a [R]");
  requireMagnitudeAtMost(request.psi, kMaxTargetHeading, "target psi [rad]");
  requirePositive(request.max_radius, "max radius [R]");
  if (request.max_radius >= kMaxCircleRadius) {
    std::ostringstream message;
    message << "max radius [R] must be < " << kMaxCircleRadius
            << " (sqrt(2)/2: larger circles reach the equator, where eq 30 is singular), got "
            << request.max_radius;
    throw std::invalid_argument(message.str());
  }
  if (request.heading_turns < 0 || request.heading_turns > kMaxHeadingTurns) {
    throw std::invalid_argument("heading turns must be in [0, " +
                                std::to_string(kMaxHeadingTurns) + "], got " +
                                std::to_string(request.heading_turns));
  }
}

PlanResult planRotorMotion(const PlanRequest& request) {
  requireValid(request);
  const LeafTable table = tabulateLeaves(request.k, request.max_radius);
  const PhaseGrid grid(table);
  PlanResult result;
  std::vector<std::string> reasons;
  for (int m = -request.heading_turns; m <= request.heading_turns; ++m) {
    const std::vector<RotorPlan> plans =
        planHeading(request, request.psi + kTwoPi * m, table, grid, reasons);
    result.solutions.insert(result.solutions.end(), plans.begin(), plans.end());
  }
  std::sort(result.solutions.begin(), result.solutions.end(),
            [](const RotorPlan& x, const RotorPlan& y) { return x.length < y.length; });
  if (result.solutions.empty()) {
    std::ostringstream text;
    text << "no plan: ";
    for (std::size_t i = 0; i < reasons.size(); ++i) text << (i ? "; " : "") << reasons[i];
    result.reason = text.str();
  }
  return result;
}

}  // namespace spherical_robots::rotor
