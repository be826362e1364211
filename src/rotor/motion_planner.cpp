#include "spherical_robots/rotor/motion_planner.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/geometric_phase.hpp"

namespace spherical_robots::rotor {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr int kUniformNodes = 64;      // leaf table nodes uniform in the geodesic radius
constexpr int kEquatorNodes = 64;      // … and uniform in log(cos 2α), dense where eq 30 stiffens
constexpr double kFiniteStep = 1e-7;   // forward-difference step of Newton's Jacobian [R]
constexpr double kResidualTolerance = 1e-12;
constexpr int kNewtonIterations = 40;
constexpr double kDuplicate = 1e-7;    // two roots closer than this in (a, b) are one [R]
constexpr double kAcceptedError = 1e-8;  // largest final_error of a reported plan
constexpr double kZeroShift = 1e-12;   // h_des below this is a pure turn [R]

/// The leaf table: radii (the first is 0, the limit where a leaf does nothing) and their phases.
struct LeafTable {
  std::vector<double> radius;
  std::vector<LeafPhase> leaf;
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
  LeafTable table;
  table.radius.push_back(0.0);
  table.leaf.emplace_back();
  for (double alpha : alphas) {
    const double r = std::min(std::sin(alpha), max_radius);
    if (r - table.radius.back() < 1e-9) continue;
    table.radius.push_back(r);
    table.leaf.push_back(leafPhase(k, r));
  }
  return table;
}

/// The equations a plan solves: η(a, b) = η_des (eq 32) and h(a, b) = h_req (eq 33), or, for a
/// pure turn (h_req = 0), η = η_des and shift = 0.
struct Equations {
  double k = 0.0;
  double eta = 0.0;
  double h = 0.0;
  bool pure_turn = false;

  Eigen::VectorXd residual(const StepPhase& phase) const {
    if (pure_turn) return Eigen::Vector3d(phase.eta - eta, phase.shift.x(), phase.shift.y());
    return Eigen::Vector2d(phase.eta - eta, phase.h - h);
  }
  Eigen::VectorXd residual(double a, double b) const { return residual(stepPhase(k, a, b)); }
};

/// Gauss-Newton (Newton for two equations) on integrated leaves from (a, b).
std::optional<Eigen::Vector2d> refine(const Equations& equations, Eigen::Vector2d x,
                                      double max_radius) {
  for (int iteration = 0; iteration < kNewtonIterations; ++iteration) {
    const Eigen::VectorXd f = equations.residual(x.x(), x.y());
    if (f.cwiseAbs().maxCoeff() < kResidualTolerance) return x;
    Eigen::MatrixXd jacobian(f.size(), 2);
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d probe = x;
      // Step inwards at the upper limit so the probe stays in the domain.
      const double step = probe[j] + kFiniteStep < max_radius ? kFiniteStep : -kFiniteStep;
      probe[j] += step;
      jacobian.col(j) = (equations.residual(probe.x(), probe.y()) - f) / step;
    }
    const Eigen::Vector2d delta = jacobian.colPivHouseholderQr().solve(-f);
    if (!delta.allFinite()) return std::nullopt;
    x += delta;
    if (x.minCoeff() <= 0.0 || x.maxCoeff() > max_radius) return std::nullopt;
    if (delta.cwiseAbs().maxCoeff() < 1e-14) break;
  }
  const Eigen::VectorXd f = equations.residual(x.x(), x.y());
  if (f.cwiseAbs().maxCoeff() < 1e3 * kResidualTolerance) return x;
  return std::nullopt;
}

bool changesSign(double a, double b, double c, double d) {
  const double lo = std::min({a, b, c, d}), hi = std::max({a, b, c, d});
  return lo <= 0.0 && hi >= 0.0;
}

/// Every root of the equations in the table's cells, refined and deduplicated.
std::vector<Eigen::Vector2d> roots(const Equations& equations, const LeafTable& table,
                                   double max_radius) {
  const std::size_t n = table.radius.size();
  std::vector<StepPhase> grid(n * n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) grid[i * n + j] = composeLeaves(table.leaf[i], table.leaf[j]);
  }
  const auto f = [&](std::size_t i, std::size_t j) { return grid[i * n + j].eta - equations.eta; };
  const auto g = [&](std::size_t i, std::size_t j) { return grid[i * n + j].h - equations.h; };
  std::vector<Eigen::Vector2d> found;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    for (std::size_t j = 0; j + 1 < n; ++j) {
      if (!changesSign(f(i, j), f(i + 1, j), f(i, j + 1), f(i + 1, j + 1))) continue;
      bool candidate;
      if (equations.pure_turn) {
        // h >= 0 touches zero instead of crossing it: accept cells where h is small compared
        // with its variation across the cell.
        const double lo = std::min({grid[i * n + j].h, grid[(i + 1) * n + j].h,
                                    grid[i * n + j + 1].h, grid[(i + 1) * n + j + 1].h});
        const double spread = std::abs(g(i + 1, j + 1) - g(i, j)) +
                              std::abs(g(i + 1, j) - g(i, j + 1));
        candidate = lo <= spread;
      } else {
        candidate = changesSign(g(i, j), g(i + 1, j), g(i, j + 1), g(i + 1, j + 1));
      }
      if (!candidate) continue;
      const Eigen::Vector2d start(0.5 * (table.radius[i] + table.radius[i + 1]),
                                  0.5 * (table.radius[j] + table.radius[j + 1]));
      const std::optional<Eigen::Vector2d> root = refine(equations, start, max_radius);
      if (!root) continue;
      const bool known = std::any_of(found.begin(), found.end(), [&](const Eigen::Vector2d& x) {
        return (x - *root).cwiseAbs().maxCoeff() < kDuplicate;
      });
      if (!known) found.push_back(*root);
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

void requireRequest(const PlanRequest& request) {
  requireFinite(request.k, "inertia ratio k");
  if (request.k < 0.0) {
    std::ostringstream message;
    message << "inertia ratio k must be >= 0, got " << request.k;
    throw std::invalid_argument(message.str());
  }
  if (request.steps < 1) {
    throw std::invalid_argument("number of steps n must be >= 1, got " +
                                std::to_string(request.steps));
  }
  requireFinite(request.u_a, "target u_a [R]");
  requireFinite(request.v_a, "target v_a [R]");
  requireFinite(request.psi, "target psi [rad]");
  requirePositive(request.max_radius, "max radius [R]");
  if (request.max_radius >= kMaxCircleRadius) {
    std::ostringstream message;
    message << "max radius [R] must be < " << kMaxCircleRadius
            << " (sqrt(2)/2: larger circles reach the equator, where eq 30 is singular), got "
            << request.max_radius;
    throw std::invalid_argument(message.str());
  }
  if (request.heading_turns < 0) {
    throw std::invalid_argument("heading turns must be >= 0, got " +
                                std::to_string(request.heading_turns));
  }
}

/// Plans for one accumulated target heading ψ; appends a reason when there is no plan.
std::vector<RotorPlan> planHeading(const PlanRequest& request, double psi, const LeafTable& table,
                                   std::vector<std::string>& reasons) {
  const int n = request.steps;
  const double h_des = std::hypot(request.u_a, request.v_a);
  std::ostringstream why;
  why << "psi = " << psi << ": ";
  Equations equations;
  equations.k = request.k;
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

  double eta_lo = 0.0, eta_hi = 0.0, h_hi = 0.0;
  for (const LeafPhase& first : table.leaf) {
    for (const LeafPhase& second : table.leaf) {
      const StepPhase phase = composeLeaves(first, second);
      eta_lo = std::min(eta_lo, phase.eta);
      eta_hi = std::max(eta_hi, phase.eta);
      h_hi = std::max(h_hi, phase.h);
    }
  }
  std::vector<RotorPlan> plans;
  int rejected = 0;
  for (const Eigen::Vector2d& root : roots(equations, table, request.max_radius)) {
    const StepPhase phase = stepPhase(request.k, root.x(), root.y());
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
    why << "no figure eight with radii a, b <= " << request.max_radius << " has eta = psi/n = "
        << equations.eta << " and h = " << equations.h << " (k = " << request.k
        << "; over that range eta spans about [" << eta_lo << ", " << eta_hi
        << "] and h reaches about " << h_hi << ")";
    if (rejected > 0) why << "; " << rejected << " root(s) failed verification";
    reasons.push_back(why.str());
  }
  return plans;
}

}  // namespace

PlanResult planRotorMotion(const PlanRequest& request) {
  requireRequest(request);
  const LeafTable table = tabulateLeaves(request.k, request.max_radius);
  PlanResult result;
  std::vector<std::string> reasons;
  for (int m = -request.heading_turns; m <= request.heading_turns; ++m) {
    const std::vector<RotorPlan> plans =
        planHeading(request, request.psi + kTwoPi * m, table, reasons);
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
