#include "spherical_robots/norma/norma_controller.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::norma {

namespace {

void requireFinitePid(const PidGains& pid, const std::string& name) {
  requireAllFinite({{pid.kp, name + " kp"}, {pid.ki, name + " ki"}, {pid.kd, name + " kd"}});
}

void requireFinitePath(const PathPoint& r) {
  requireAllFinite({{r.x, "desired x"},
                    {r.y, "desired y"},
                    {r.x_dot, "desired x_dot"},
                    {r.y_dot, "desired y_dot"},
                    {r.x_ddot, "desired x_ddot"},
                    {r.y_ddot, "desired y_ddot"}});
}

// Eqs 48-51 on checked input: the controller checks once per evaluation, not twice.
KinematicCommand paperKinematics(const KinematicGains& gains, double R, double x, double y,
                                 double psi, const PathPoint& reference) {
  const double ex = x - reference.x;  // eq 48
  const double ey = y - reference.y;
  KinematicCommand out;
  out.error = std::sqrt(ex * ex + ey * ey);
  // Eq 49 from e to the heading h: ‖e‖ sin ζ = e × h, ‖e‖ cos ζ = e · h.
  const auto [s, c] = sinCos(psi);
  const double e_sin = ex * s - ey * c;
  const double e_cos = ex * c + ey * s;
  out.zeta = std::atan2(e_sin, e_cos);
  const double gain = 1.0 / (gains.k3 + out.error);  // ‖e‖ / (k3 + ‖e‖) over ‖e‖
  out.delta_d = gains.k1 * gain * e_sin;              // eq 50
  out.theta_dot_d = std::sqrt(reference.x_dot * reference.x_dot +
                              reference.y_dot * reference.y_dot) / R +
                    gains.k2 * gain * e_cos;  // eq 51
  return out;
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
  return paperKinematics(gains, R, x, y, psi, reference);
}

void validate(const ControllerGains& g) {
  requireFinite(g.kinematic.k1, "k1");
  requireFinite(g.kinematic.k2, "k2");
  requirePositive(g.kinematic.k3, "k3");
  requireFinitePid(g.rate, "PID1");
  requireFinitePid(g.pendulum, "PID2");
  requireFinitePid(g.slider, "PID3");
  requireFinitePid(g.tracking_slider, "tracking slider PID");
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
  const double speed_sq = r.x_dot * r.x_dot + r.y_dot * r.y_dot;
  const double speed = std::sqrt(speed_sq);
  const double path_yaw_rate =
      speed_sq > 0.0 ? (r.x_dot * r.y_ddot - r.y_dot * r.x_ddot) / speed_sq : 0.0;
  const auto [s, c] = sinCos(psi);
  // The path's direction in the robot's heading frame: speed (cos, sin) of the heading error.
  const double path_along = c * r.x_dot + s * r.y_dot;
  const double path_across = -s * r.x_dot + c * r.y_dot;
  const double ex = r.x - x, ey = r.y - y;
  const double along = c * ex + s * ey;
  const double cross = -s * ex + c * ey;

  KinematicCommand out;
  out.error = std::sqrt(ex * ex + ey * ey);
  out.zeta = std::atan2(-ex * s + ey * c, -ex * c - ey * s);  // eq 49 with e = r − r_d
  const double cos_phi = std::cos(q(2));
  out.theta_dot_d = (path_along + g.along_gain * along) / (p.R * cos_phi);  // eq 12
  // speed · sin(ψ_r − ψ) = path_across.
  const double yaw_rate = path_yaw_rate + g.cross_gain * speed * cross + g.heading_gain * path_across;
  // Eq 6 solved for the tilt, sin φ_d = −ψ̇_d / θ̇_d, with θ̇_d regularised near zero and the tilt
  // saturated smoothly (tanh) so that the closed loop stays smooth for the stiff integrator.
  const double rate_floor = 0.005 / p.R;
  const double sin_phi = -yaw_rate * out.theta_dot_d /
                         (out.theta_dot_d * out.theta_dot_d + rate_floor * rate_floor);
  // Leave a fifth of the stroke to the tilt feedback.
  const double max_tilt = std::atan(0.8 * p.m_slider * g.max_slider / (p.m_pendulum * p.L));
  const double phi_d = max_tilt * std::tanh(std::atan(sin_phi) / max_tilt);
  // G3 = 0 with m_P L0 = m_Sl δ0 (eq 1): m_Sl δ C_φ + m_P L C_β S_φ = 0.
  const double held =
      -p.m_pendulum * p.L * std::cos(q(1) - q(0)) * std::tan(phi_d) / p.m_slider;
  const double slider = held + g.tilt_gain * (q(2) - phi_d) + g.tilt_damping * qd(2);
  out.delta_d = g.max_slider * std::tanh(slider / g.max_slider);
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
  requireFinite(x, "X");
  requireFinite(y, "Y");
  requireFinite(psi, "psi");
  requireFinitePath(reference);
  const KinematicCommand command =
      kind_ == ControllerKind::kPaper
          ? paperKinematics(gains_.kinematic, parameters_.R, x, y, psi, reference)
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
  const PidGains& slider = kind_ == ControllerKind::kPaper ? g.slider : g.tracking_slider;
  const double slider_error = command.delta_d - q(3);
  out.force = slider.kp * slider_error + slider.ki * integrals(2) - slider.kd * qd(3) +
              parameters_.g * parameters_.m_slider * std::sin(q(2));
  out.integrand = Eigen::Vector3d(rate_error, beta_error, slider_error);
  return out;
}

void NormaController::setGains(const ControllerGains& gains) {
  validate(gains);
  gains_ = gains;
}

}  // namespace spherical_robots::norma
