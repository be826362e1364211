#include "spherical_robots/rotor/plan_execution.hpp"

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/rotor/contact_curve.hpp"

namespace spherical_robots::rotor {
namespace {

using PlantVector = std::array<double, 5>;  // u_a, v_a, u_o, v_o, ψ

ContactCoordinates fromVector(const PlantVector& x) { return {x[0], x[1], x[2], x[3], x[4]}; }
PlantVector toVector(const ContactCoordinates& c) { return {c.u_a, c.v_a, c.u_o, c.v_o, c.psi}; }
PlantVector toVector(const ContactRates& r) { return {r.u_a, r.v_a, r.u_o, r.v_o, r.psi}; }

/// θ of the sin² ramp from rest after time s in [0, ramp]: ∫ M sin²(π τ / 2 ramp) dτ.
double rampTheta(double max_rate, double ramp, double s) {
  if (ramp == 0.0) return 0.0;
  return max_rate * (0.5 * s - ramp / (2.0 * M_PI) * std::sin(M_PI * s / ramp));
}

double rampRate(double max_rate, double ramp, double s) {
  if (ramp == 0.0) return max_rate;
  const double sine = std::sin(0.5 * M_PI * s / ramp);
  return max_rate * sine * sine;
}

void requireSteps(int steps) {
  if (steps < 1) throw std::invalid_argument("steps must be >= 1, got " + std::to_string(steps));
}

}  // namespace

CurveTiming::CurveTiming(int steps, double max_rate, double ramp_time)
    : steps_(steps), max_rate_(max_rate), ramp_time_(ramp_time) {
  requireSteps(steps);
  requirePositive(max_rate, "curve rate [rad/s]");
  requireFinite(ramp_time, "ramp time [s]");
  if (ramp_time < 0.0) {
    throw std::invalid_argument("ramp time [s] must be >= 0, got " + std::to_string(ramp_time));
  }
  const double total = 2.0 * M_PI * steps;
  if (max_rate * ramp_time > total) {
    std::ostringstream message;
    message << "ramp time [s] must be <= 2 pi n / curve rate = " << total / max_rate << ", got "
            << ramp_time;
    throw std::invalid_argument(message.str());
  }
}

double CurveTiming::duration() const { return 2.0 * M_PI * steps_ / max_rate_ + ramp_time_; }

double CurveTiming::theta(double t) const {
  requireFinite(t, "time [s]");
  const double end = duration();
  const double total = 2.0 * M_PI * steps_;
  if (t <= 0.0) return 0.0;
  if (t >= end) return total;
  if (t < ramp_time_) return rampTheta(max_rate_, ramp_time_, t);
  if (t > end - ramp_time_) return total - rampTheta(max_rate_, ramp_time_, end - t);
  return 0.5 * max_rate_ * ramp_time_ + max_rate_ * (t - ramp_time_);
}

double CurveTiming::rate(double t) const {
  requireFinite(t, "time [s]");
  const double end = duration();
  if (t <= 0.0 || t >= end) return 0.0;
  if (t < ramp_time_) return rampRate(max_rate_, ramp_time_, t);
  if (t > end - ramp_time_) return rampRate(max_rate_, ramp_time_, end - t);
  return max_rate_;
}

RotorSpeeds planSetPoint(double k, double inertia_scale, const FigureEight& curve, int steps,
                         double theta, double theta_rate) {
  requireSteps(steps);
  requireFinite(theta, "curve parameter theta [rad]");
  const double total = 2.0 * M_PI * steps;
  if (theta < 0.0 || theta > total) {
    std::ostringstream message;
    message << "curve parameter theta [rad] must be in [0, " << total << "], got " << theta;
    throw std::invalid_argument(message.str());
  }
  const int step = std::max(static_cast<int>(std::ceil(theta / (2.0 * M_PI))) - 1, 0);
  const double local = std::clamp(theta - 2.0 * M_PI * step, 0.0, 2.0 * M_PI);
  // The leaf of radius a gets 2π a/(a + b) of the step's θ: the contact then runs at (a + b) θ̇
  // on both leaves (2a dθ_leaf/dθ = 2b dθ_leaf/dθ = a + b), so the set-points do not step at
  // the pole where the leaves meet.
  const double split = 2.0 * M_PI * curve.a() / (curve.a() + curve.b());
  const bool second = local > split;
  const double leaf_rate = second ? M_PI / (2.0 * M_PI - split) : M_PI / split;  // dθ_leaf/dθ
  const double leaf_theta = second ? M_PI + (local - split) * leaf_rate : local * leaf_rate;
  const CurvePoint c = curve.onLeaf(second, std::clamp(leaf_theta, 0.0, 2.0 * M_PI));
  const Eigen::Vector2d angles = contactAngles(c.point);
  // ψ = 0 and the origin: the speeds are the same at every heading and place (header).
  const ContactCoordinates at{0.0, 0.0, angles.x(), angles.y(), 0.0};
  return rotorSpeeds(k, inertia_scale, at,
                     curveAngularVelocity(k, c, 0.0, theta_rate * leaf_rate));
}

RotorSpeeds planSetPointAt(double k, double inertia_scale, const FigureEight& curve,
                           const CurveTiming& timing, double t) {
  return planSetPoint(k, inertia_scale, curve, timing.steps(), timing.theta(t), timing.rate(t));
}

RotorSpeeds lagCompensatedSetPoint(const SetPointSchedule& schedule, double t,
                                   double time_constant, double h) {
  requireFinite(time_constant, "actuator time constant [s]");
  if (time_constant < 0.0) {
    throw std::invalid_argument("actuator time constant [s] must be >= 0, got " +
                                std::to_string(time_constant));
  }
  requirePositive(h, "command period [s]");
  const RotorSpeeds now = schedule(t);
  if (time_constant == 0.0) return now;
  const RotorSpeeds next = schedule(t + h);
  const double gain = time_constant / h;
  return {now.phi1 + gain * (next.phi1 - now.phi1), now.phi2 + gain * (next.phi2 - now.phi2)};
}

double peakRotorSpeed(const std::function<RotorSpeeds(double theta)>& at_unit_rate) {
  constexpr int kSamples = 4000;
  double peak = 0.0;
  for (int i = 0; i <= kSamples; ++i) {
    const RotorSpeeds s = at_unit_rate(2.0 * M_PI * i / kSamples);
    peak = std::max({peak, std::abs(s.phi1), std::abs(s.phi2)});
  }
  return peak;
}

double peakRotorSpeed(double k, double inertia_scale, const FigureEight& curve) {
  return peakRotorSpeed(
      [&](double theta) { return planSetPoint(k, inertia_scale, curve, 1, theta, 1.0); });
}

ContactRates plantRates(double k, double inertia_scale, const ContactCoordinates& coordinates,
                        const RotorSpeeds& speeds) {
  return contactRates(coordinates, rotorAngularVelocity(k, inertia_scale, coordinates, speeds));
}

ContactCoordinates advancePlant(double k, double inertia_scale, const ContactCoordinates& start,
                                const RotorSpeeds& speeds, double duration, double step) {
  requireFinite(duration, "duration [s]");
  requirePositive(step, "integration step [s]");
  if (duration < 0.0) {
    throw std::invalid_argument("duration [s] must be >= 0, got " + std::to_string(duration));
  }
  const int steps = static_cast<int>(std::ceil(duration / step - 1e-9));
  if (steps == 0) return start;
  PlantVector x = toVector(start);
  boost::numeric::odeint::integrate_n_steps(
      boost::numeric::odeint::runge_kutta4<PlantVector>(),
      [&](const PlantVector& s, PlantVector& dxdt, double) {
        dxdt = toVector(plantRates(k, inertia_scale, fromVector(s), speeds));
      },
      x, 0.0, duration / steps, steps);
  for (const double value : x) {
    if (!std::isfinite(value)) {
      throw std::invalid_argument("the rotor sphere's state turned non-finite while integrating");
    }
  }
  return fromVector(x);
}

ContactCoordinates executePlan(double k, double inertia_scale, const FigureEight& curve,
                               const CurveTiming& timing, double period, double settle) {
  requireFinite(period, "set-point period [s]");
  requireFinite(settle, "settle time [s]");
  if (period < 0.0 || settle < 0.0) {
    throw std::invalid_argument("set-point period and settle time [s] must be >= 0");
  }
  if (period == 0.0) {
    // Speeds ∝ θ̇ and the plant's rates are linear in them, so the end state does not depend on
    // the timing: integrate in θ at θ̇ = 1, leaf by leaf (their curvatures differ at the pole).
    PlantVector x{};
    for (int step = 0; step < timing.steps(); ++step) {
      for (const bool second : {false, true}) {
        const auto rhs = [&](const PlantVector& s, PlantVector& dxdt, double theta) {
          const CurvePoint c = curve.onLeaf(second, theta);
          const Eigen::Vector2d angles = contactAngles(c.point);
          const ContactCoordinates on_curve{0.0, 0.0, angles.x(), angles.y(), 0.0};
          const RotorSpeeds speeds =
              rotorSpeeds(k, inertia_scale, on_curve, curveAngularVelocity(k, c, 0.0, 1.0));
          dxdt = toVector(plantRates(k, inertia_scale, fromVector(s), speeds));
        };
        const double lo = second ? M_PI : 0.0;
        boost::numeric::odeint::integrate_adaptive(
            boost::numeric::odeint::make_controlled<
                boost::numeric::odeint::runge_kutta_dopri5<PlantVector>>(1e-12, 1e-12),
            rhs, x, lo, lo + M_PI, 0.01);
      }
    }
    return fromVector(x);
  }
  ContactCoordinates x;
  const double end = timing.duration() + settle;
  const double step = std::min(period, 1e-3);
  for (long i = 0; i * period < end; ++i) {
    const double t = i * period;
    const RotorSpeeds speeds = planSetPointAt(k, inertia_scale, curve, timing, t);
    x = advancePlant(k, inertia_scale, x, speeds, std::min(period, end - t), step);
  }
  return x;
}

}  // namespace spherical_robots::rotor
