#include "spherical_robots/freebot/src_inverse_kinematics.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::freebot {
namespace {

void requireValidOptions(const IkOptions& options) {
  requireAllPositive({{options.position_tolerance, "IK position tolerance [m]"},
                      {options.orientation_tolerance, "IK orientation tolerance [rad]"},
                      {options.position_gain, "IK position gain K_p [1/s]"},
                      {options.orientation_gain, "IK orientation gain K_a [1/s]"},
                      {options.step, "IK step [s]"}});
  requireNonNegative(options.singular_region, "IK singular region xi");
  requireNonNegative(options.max_damping, "IK maximum damping lambda_max");
  requireNonNegative(options.damping_residual, "IK damping residual");
  requireAtLeast(options.max_iterations, 1, "IK max_iterations");
  requireAtLeast(options.stall_window, 1, "IK stall_window");
  requireAtLeast(options.restarts, 0, "IK restarts");
  requirePositive(options.max_joint_step, "IK max_joint_step [rad]");
}

/// A configuration to restart from: every joint rolled straight by a random rotation vector of
/// length below π in a uniformly random direction.
std::vector<SrcJointState> randomConfiguration(const SrcManipulator& manipulator,
                                               std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector2d> vectors(manipulator.jointCount());
  for (Eigen::Vector2d& v : vectors) {
    const double angle = 2.0 * M_PI * unit(rng);
    const double length = M_PI * std::sqrt(unit(rng));  // uniform over the disc of radius π
    v = length * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  }
  return manipulator.straightRolls(vectors);
}

}  // namespace

Eigen::Vector3d orientationError(const Eigen::Quaterniond& current,
                                 const Eigen::Quaterniond& desired) {
  const double eta = current.w();
  const double eta_d = desired.w();
  const Eigen::Vector3d eps = current.vec();
  const Eigen::Vector3d eps_d = desired.vec();
  return eta * eps_d - eta_d * eps - eps_d.cross(eps);  // eq 47
}

double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  const double w = std::abs(a.dot(b));
  const double s = (b * a.conjugate()).vec().norm();
  return 2.0 * std::atan2(s, w);
}

Eigen::VectorXd dampedLeastSquares(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& twist,
                                   double singular_region, double max_damping) {
  // Eq 39's SVD from the eigen-decomposition of the smaller Gram matrix (at most 6 × 6, as J has
  // at most 6 rows): J J^T = U Σ² U^T when J is wide, J^T J = V Σ² V^T when it is tall. Fixed
  // maximum sizes keep the solver off the heap; it is the IK's inner loop.
  using Gram = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
  const bool wide = jacobian.rows() <= jacobian.cols();
  const Gram gram =
      wide ? Gram(jacobian * jacobian.transpose()) : Gram(jacobian.transpose() * jacobian);
  const Eigen::SelfAdjointEigenSolver<Gram> eigen(gram);
  const Eigen::Index count = gram.rows();  // min(m, 2n) singular values
  // Eigenvalues come in increasing order: σ_k² = eigenvalue(count − 1 − k), σ_1 first.
  const auto sigma = [&](Eigen::Index k) {
    return std::sqrt(std::max(0.0, eigen.eigenvalues()(count - 1 - k)));
  };
  const double zero = sigma(0) * 1e-10;
  Eigen::Index rank = 0;
  while (rank < count && sigma(rank) > zero) {
    ++rank;
  }
  double damping2 = 0.0;  // eq 44
  if (rank > 0 && sigma(count - 1) < singular_region) {
    const double ratio = sigma(rank - 1) / singular_region;
    // Eq 44 as printed turns negative when J is rank deficient and σ_r > ξ (F6): no damping then.
    damping2 = std::max(0.0, (1.0 - ratio * ratio) * max_damping * max_damping);
  }
  // Eqs 42, 43: ω = Σ_k v_k σ_k / (σ_k² + λ²) u_k^T x, with J^T u_k = σ_k v_k (wide) or
  // u_k^T x = v_k^T J^T x / σ_k (tall).
  const Eigen::VectorXd projected =
      wide ? Eigen::VectorXd(twist) : Eigen::VectorXd(jacobian.transpose() * twist);
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(count);
  for (Eigen::Index k = 0; k < rank; ++k) {
    const Eigen::Index column = count - 1 - k;
    const double s = sigma(k);
    weights(column) = eigen.eigenvectors().col(column).dot(projected) / (s * s + damping2);
  }
  const Eigen::VectorXd combined = eigen.eigenvectors() * weights;
  return wide ? Eigen::VectorXd(jacobian.transpose() * combined) : combined;
}

IkResult solveIk(const SrcManipulator& manipulator, const Eigen::Vector3d& target_position,
                 const Eigen::Quaterniond& target_orientation,
                 const std::vector<SrcJointState>& seed, const IkOptions& options) {
  requireValidOptions(options);
  requireMagnitudeAtMost(target_position.x(), kMaxLength, "target x [m]");
  requireMagnitudeAtMost(target_position.y(), kMaxLength, "target y [m]");
  requireMagnitudeAtMost(target_position.z(), kMaxLength, "target z [m]");
  const bool full_pose = options.mode == IkMode::FullPose;
  if (full_pose) {
    requireUnit(target_orientation, "target orientation");
  }
  if (!seed.empty()) {
    manipulator.requireValid(seed);
  }

  // The residual DLS reduces, r = [e_p; δ] (eqs 45-47 without the gains, which are equal):
  // ‖r‖² = ‖e_p‖² + sin²(θ/2), the merit of the line search.
  const auto merit = [&](const LinkPose& end) {
    const double position = (target_position - end.position).squaredNorm();
    if (!full_pose) {
      return position;
    }
    const double half_sine = std::sin(0.5 * angleBetween(end.orientation, target_orientation));
    return position + half_sine * half_sine;
  };

  std::mt19937 rng(options.seed);
  IkResult best;
  double best_score = std::numeric_limits<double>::infinity();
  const Eigen::Index rows = full_pose ? 6 : 3;
  Eigen::VectorXd twist(rows);

  for (int start = 0; start <= options.restarts; ++start) {
    std::vector<SrcJointState> joints;
    if (start > 0) {
      joints = randomConfiguration(manipulator, rng);
    } else if (!seed.empty()) {
      joints = seed;
    } else {
      joints.assign(manipulator.jointCount(), SrcJointState{});
    }
    ++best.starts;
    double window_merit = 0.0;
    for (int iteration = 0;; ++iteration) {
      LinkPose end;
      const Eigen::MatrixXd jacobian = manipulator.jacobian(joints, end);
      const Eigen::Vector3d position_error = target_position - end.position;
      const double position_norm = position_error.norm();
      const double angle = full_pose ? angleBetween(end.orientation, target_orientation) : 0.0;
      // Errors in units of their tolerances, so that neither dominates the choice of the best.
      const double score = std::pow(position_norm / options.position_tolerance, 2) +
                           std::pow(angle / options.orientation_tolerance, 2);
      if (score < best_score) {
        best_score = score;
        best.joints = joints;
        best.end = end;
        best.position_error = position_norm;
        best.orientation_error = angle;
      }
      if (position_norm <= options.position_tolerance && angle <= options.orientation_tolerance) {
        best.success = true;
        return best;
      }
      const double current_merit = merit(end);
      if (iteration >= options.max_iterations) {
        break;
      }
      if (iteration % options.stall_window == 0) {
        // Stuck: the residual fell by less than 0.02 % over the last window.
        if (iteration > 0 && current_merit > (1.0 - 2e-4) * window_merit) {
          break;
        }
        window_merit = current_merit;
      }
      twist.head<3>() = options.position_gain * position_error;  // eq 45, fixed target
      if (full_pose) {
        // q^d and −q^d are one orientation; the one nearer q makes δ the short way round.
        const Eigen::Quaterniond desired = end.orientation.dot(target_orientation) < 0.0
                                               ? Eigen::Quaterniond(-target_orientation.coeffs())
                                               : target_orientation;
        twist.tail<3>() =
            options.orientation_gain * orientationError(end.orientation, desired);  // eq 46
      }
      // Eq 44's damping bounds the joint rates near a singular configuration, but it also stops
      // the solver short of a target that lies near one (F7). It is applied in full while the
      // residual ‖r‖ >= damping_residual and fades with ‖r‖ below, so the last steps are plain
      // Gauss-Newton steps.
      const double fade = options.damping_residual > 0.0
                              ? std::min(1.0, std::sqrt(current_merit) / options.damping_residual)
                              : 1.0;
      const Eigen::VectorXd velocity =
          dampedLeastSquares(jacobian.topRows(rows), twist, options.singular_region,
                             fade * options.max_damping);  // eq 42
      // Near a singularity the DLS velocity can be huge: no joint rolls more than
      // max_joint_step per iteration (the direction is kept) ...
      double largest = 0.0;
      for (Eigen::Index k = 0; k + 1 < velocity.size(); k += 2) {
        largest = std::max(largest, velocity.segment<2>(k).norm());
      }
      double dt = std::min(options.step, options.max_joint_step / std::max(largest, 1e-300));
      // ... and a step that does not reduce the residual is halved (at most kHalvings times):
      // the DLS direction descends ‖r‖², so this converges where the plain step would
      // oscillate (a target out of reach pulls the chain into the stretched singularity).
      constexpr int kHalvings = 10;
      bool moved = false;
      for (int halving = 0; halving <= kHalvings && !moved; ++halving, dt *= 0.5) {
        std::vector<SrcJointState> trial = manipulator.roll(joints, velocity, dt);
        if (merit(manipulator.endEffector(trial)) < current_merit) {
          joints = std::move(trial);
          moved = true;
        }
      }
      ++best.iterations;
      if (!moved) {
        break;
      }
    }
  }
  return best;
}

}  // namespace spherical_robots::freebot
