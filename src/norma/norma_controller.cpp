#include "spherical_robots/norma/norma_controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::norma {
namespace {

double wrapAngle(double angle) { return std::atan2(std::sin(angle), std::cos(angle)); }

void requireFinitePid(const PidGains& pid, const std::string& name) {
  requireFinite(pid.kp, name + " kp");
  requireFinite(pid.ki, name + " ki");
  requireFinite(pid.kd, name + " kd");
}

void requireNonNegative(double value, const std::string& what) {
  requireFinite(value, what);
  if (value < 0.0) {
    throw std::invalid_argument(what + " must be >= 0, got " + std::to_string(value));
  }
}

void requireFinitePath(const PathPoint& r) {
  requireFinite(r.x, "desired x");
  requireFinite(r.y, "desired y");
  requireFinite(r.x_dot, "desired x_dot");
  requireFinite(r.y_dot, "desired y_dot");
  requireFinite(r.x_ddot, "desired x_ddot");
  requireFinite(r.y_ddot, "desired y_ddot");
}

}  // namespace

KinematicCommand kinematicLayer(const KinematicGains& gains, double R, double x, double y,
                                double psi, const PathPoint& reference) {
  requireFinite(gains.k1, "k1");
  requireFinite(gains.k2, "k2");
  requirePositive(gains.k3, "k3");
  requirePositive(R, "R [m]");
  requireFinite(x, "X");
  requireFinite(y, "Y");
  requireFinite(psi, "psi");
  requireFinitePath(reference);
  const double ex = x - reference.x;  // eq 48
  const double ey = y - reference.y;
  KinematicCommand out;
  out.error = std::hypot(ex, ey);
  out.zeta = wrapAngle(psi - std::atan2(ey, ex));  // eq 49, from e to the heading
  const double normalized = out.error / (gains.k3 + out.error);
  out.delta_d = gains.k1 * normalized * std::sin(out.zeta);  // eq 50
  out.theta_dot_d = std::hypot(reference.x_dot, reference.y_dot) / R +
                    gains.k2 * normalized * std::cos(out.zeta);  // eq 51
  return out;
}

void validate(const ControllerGains& g) {
  requireFinite(g.kinematic.k1, "k1");
  requireFinite(g.kinematic.k2, "k2");
  requirePositive(g.kinematic.k3, "k3");
  requireFinitePid(g.rate, "PID1");
  requireFinitePid(g.pendulum, "PID2");
  requireFinitePid(g.slider, "PID3");
  if (g.rate.kd != 0.0) {
    throw std::invalid_argument("PID1 kd must be 0 (a derivative on the measured rolling rate "
                                "needs the acceleration), got " + std::to_string(g.rate.kd));
  }
  requireNonNegative(g.along_gain, "along-track gain");
  requireNonNegative(g.cross_gain, "cross-track gain");
  requireNonNegative(g.heading_gain, "heading gain");
  requireNonNegative(g.tilt_gain, "tilt gain");
  requireNonNegative(g.tilt_damping, "tilt damping");
  requirePositive(g.max_slider, "max slider [m]");
}

NormaController::NormaController(const NormaParameters& parameters, ControllerKind kind,
                                 const ControllerGains& gains)
    : parameters_(parameters), kind_(kind), gains_(gains) {
  validate(parameters_);
  validate(gains_);
}

KinematicCommand NormaController::trackingLayer(const Vector4& q, const Vector4& qd, double x,
                                                double y, double psi,
                                                const PathPoint& r) const {
  const NormaParameters& p = parameters_;
  const ControllerGains& g = gains_;
  const double speed = std::hypot(r.x_dot, r.y_dot);
  const double path_heading = std::atan2(r.y_dot, r.x_dot);
  const double path_yaw_rate =
      speed > 0.0 ? (r.x_dot * r.y_ddot - r.y_dot * r.x_ddot) / (speed * speed) : 0.0;
  const double ex = r.x - x, ey = r.y - y;
  const double c = std::cos(psi), s = std::sin(psi);
  const double along = c * ex + s * ey;
  const double cross = -s * ex + c * ey;
  const double heading_error = wrapAngle(path_heading - psi);

  KinematicCommand out;
  out.error = std::hypot(ex, ey);
  out.zeta = wrapAngle(psi - std::atan2(-ey, -ex));
  const double cos_phi = std::cos(q(2));
  const double v = speed * std::cos(heading_error) + g.along_gain * along;
  out.theta_dot_d = v / (p.R * cos_phi);  // eq 12 along the heading
  const double yaw_rate =
      path_yaw_rate + speed * (g.cross_gain * cross + g.heading_gain * std::sin(heading_error));
  // Eq 6 solved for the tilt; the rolling rate that divides is kept away from zero.
  const double min_rate = 0.02 / p.R;
  const double rate = std::copysign(std::max(std::abs(out.theta_dot_d), min_rate),
                                    out.theta_dot_d);
  const double max_tilt = std::atan(p.m_slider * g.max_slider / (p.m_pendulum * p.L));
  const double phi_d =
      std::clamp(std::asin(std::clamp(-yaw_rate / rate, -1.0, 1.0)), -max_tilt, max_tilt);
  // G3 = 0 with m_P L0 = m_Sl δ0 (eq 1): m_Sl δ C_φ + m_P L C_β S_φ = 0.
  const double held = -p.m_pendulum * p.L * std::cos(q(1) - q(0)) * std::tan(phi_d) /
                      p.m_slider;
  out.delta_d = std::clamp(held + g.tilt_gain * (q(2) - phi_d) + g.tilt_damping * qd(2),
                           -g.max_slider, g.max_slider);
  return out;
}

ControlOutput NormaController::compute(const Vector4& q, const Vector4& qd, double x, double y,
                                       double psi, const Eigen::Vector3d& integrals,
                                       const PathPoint& reference) const {
  for (int i = 0; i < 4; ++i) {
    requireFinite(q(i), "q");
    requireFinite(qd(i), "qd");
  }
  for (int i = 0; i < 3; ++i) requireFinite(integrals(i), "controller integral");
  const KinematicCommand command =
      kind_ == ControllerKind::kPaper
          ? kinematicLayer(gains_.kinematic, parameters_.R, x, y, psi, reference)
          : trackingLayer(q, qd, x, y, psi, reference);
  const ControllerGains& g = gains_;
  ControlOutput out;
  out.theta_dot_d = command.theta_dot_d;
  out.delta_d = command.delta_d;
  out.error = command.error;
  // Fig. 5, upper loop: PID1 sets the pendulum angle β = α − θ, PID2 holds it.
  const double rate_error = command.theta_dot_d - qd(0);
  out.beta_d = g.rate.kp * rate_error + g.rate.ki * integrals(0);
  const double beta = q(1) - q(0);
  const double beta_error = out.beta_d - beta;
  out.torque = g.pendulum.kp * beta_error + g.pendulum.ki * integrals(1) -
               g.pendulum.kd * (qd(1) - qd(0));
  // Fig. 5, lower loop: PID3 on δ plus the feed-forward that holds the slider against gravity.
  const double slider_error = command.delta_d - q(3);
  out.force = g.slider.kp * slider_error + g.slider.ki * integrals(2) - g.slider.kd * qd(3) +
              parameters_.g * parameters_.m_slider * std::sin(q(2));
  out.integrand = Eigen::Vector3d(rate_error, beta_error, slider_error);
  return out;
}

}  // namespace spherical_robots::norma
