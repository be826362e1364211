#pragma once
// A lower bound for `sphere_sim terrain --robot 3R --path circle --law smooth` (issue 13's 10 ms
// target): the same closed loop (eq 59 surface, eq 60 circle, the smooth law, the paper contact
// model, RK4 at dt = 5 ms, the law at every stage) written as straight-line arithmetic, with no
// input checks, no virtual calls and nothing passed through memory between the surface, the
// frames and the law. Not the product: what restructuring the core could approach. Its numbers
// are config/terrain.yaml's and the URDF's; bench_terrain's BM_TerrainStageFloor fails unless
// the floor ends where the core's TerrainSimulation, built from those files, ends.

#include <array>
#include <cmath>

#include "spherical_robots/core/sin_cos.hpp"

namespace spherical_robots::bench {

/// The shipped 3R circle scenario (config/terrain.yaml).
struct FloorScenario {
  double amplitude = 0.2;      ///< a [m], eq 59
  double frequency = 2.0;      ///< w [rad/m]
  double path_radius = 2.0;    ///< [m], eq 60
  double path_rate = 0.05;     ///< [rad/s]
  double window = 0.5;         ///< tau [s], centred on t
  double approach_speed = 0.5; ///< v_c [m/s]
  double along_gain = 4.0;     ///< K_a [1/s]
  double cross_gain = 3.0;     ///< K_c [1/s]
  double heading_gain = 2.0;   ///< k_h [1/s]
  double min_speed = 0.01;     ///< v_e [m/s]
};

/// p_d, the windowed velocity w on the surface and w / sqrt(|w|^2 + v_e^2), at one time.
struct FloorDesired {
  double p[3];
  double w[3];
  double along[3];
};

inline FloorDesired floorDesired(const FloorScenario& s, double t) {
  const auto [sin_wt, cos_wt] = sinCos(s.path_rate * t);
  const double half_turn = 0.5 * s.path_rate * s.window;
  const double speed = s.path_radius * s.path_rate * std::sin(half_turn) / half_turn;
  FloorDesired d{};
  d.p[0] = s.path_radius * cos_wt;
  d.p[1] = s.path_radius * sin_wt;
  d.w[0] = -speed * sin_wt;
  d.w[1] = speed * cos_wt;
  const auto [x, y] = sinCos(s.frequency * d.p[0], s.frequency * d.p[1]);
  d.p[2] = s.amplitude * (x.cos + y.cos - 2.0);
  const double slope = -s.amplitude * s.frequency;
  d.w[2] = slope * (x.sin * d.w[0] + y.sin * d.w[1]);
  const double inverse = 1.0 / std::sqrt(d.w[0] * d.w[0] + d.w[1] * d.w[1] + d.w[2] * d.w[2] +
                                         s.min_speed * s.min_speed);
  for (int i = 0; i < 3; ++i) d.along[i] = d.w[i] * inverse;
  return d;
}

/// What sphere_sim's CSV row holds beyond the state and p_d.
struct FloorRow {
  double height, error_norm, zeta, centre[3], roll_rate, lateral_rate, turn_rate;
};

/// (x', y', psi') of the 3R robot at state (x, y, psi); with kRow, also the row's other values
/// for a sphere of radius [m] (the rate of the paper model's contact point does not depend on it).
template <bool kRow>
inline std::array<double, 3> floorStateRate(const FloorScenario& s, const double* state,
                                            const FloorDesired& d, double radius = 0.0,
                                            FloorRow* row = nullptr) {
  const auto [x, y] = sinCos(s.frequency * state[0], s.frequency * state[1]);
  const SinCos heading = sinCos(state[2]);
  const double slope = -s.amplitude * s.frequency;
  const double gx = slope * x.sin;
  const double gy = slope * y.sin;
  const double length = std::sqrt(1.0 + gx * gx + gy * gy);  // the tangent frame, eqs 19/23
  const double dd = 1.0 / (length * (length + 1.0));
  const double c = (length + 1.0) * dd;
  const double t0[3] = {1.0 - dd * gx * gx, -dd * gx * gy, c * gx};
  const double t1[3] = {-dd * gx * gy, 1.0 - dd * gy * gy, c * gy};
  double h[3];
  double l[3];
  for (int i = 0; i < 3; ++i) {
    h[i] = heading.cos * t0[i] + heading.sin * t1[i];
    l[i] = -heading.sin * t0[i] + heading.cos * t1[i];
  }
  const double height = s.amplitude * (x.cos + y.cos - 2.0);
  const double e[3] = {d.p[0] - state[0], d.p[1] - state[1], d.p[2] - height};
  const double e_along = e[0] * d.along[0] + e[1] * d.along[1] + e[2] * d.along[2];
  double k[3];
  for (int i = 0; i < 3; ++i) {
    k[i] = s.cross_gain * e[i] + (s.along_gain - s.cross_gain) * e_along * d.along[i];
  }
  const double denominator =
      s.approach_speed + std::sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
  double forward_d = 0.0;
  double leftward_d = 0.0;
  for (int i = 0; i < 3; ++i) {
    forward_d += denominator * d.w[i] * h[i] + s.approach_speed * k[i] * h[i];
    leftward_d += denominator * d.w[i] * l[i] + s.approach_speed * k[i] * l[i];
  }
  const double floor_d = s.min_speed * denominator;
  const double forward = forward_d / denominator;
  const double leftward = leftward_d / denominator;
  const double turn = s.heading_gain * leftward_d /
                      std::sqrt(forward_d * forward_d + leftward_d * leftward_d + floor_d * floor_d);
  if constexpr (kRow) {
    const double n[3] = {c * -gx, c * -gy, c};
    *row = {height,
            std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]),
            std::atan2(e[0] * l[0] + e[1] * l[1] + e[2] * l[2], e[0] * h[0] + e[1] * h[1] + e[2] * h[2]),
            {state[0] + radius * n[0], state[1] + radius * n[1], height + radius * n[2]},
            forward / radius,
            -leftward / radius,
            turn};
  }
  return {forward * h[0] + leftward * l[0], forward * h[1] + leftward * l[1], turn};
}

/// Runs from the origin, heading +x, for steps of dt [s]; rows(t, state, desired) after every
/// rows_every steps and at t = 0, if rows_every > 0. @return the final (x, y, psi).
template <typename Rows>
std::array<double, 3> runFloor(const FloorScenario& s, int steps, double dt, int rows_every,
                               Rows rows) {
  std::array<double, 3> state = {0.0, 0.0, 0.0};
  FloorDesired start = floorDesired(s, 0.0);
  if (rows_every > 0) rows(0.0, state, start);
  for (int n = 0; n < steps; ++n) {
    const double t = n * dt;
    const FloorDesired middle = floorDesired(s, t + 0.5 * dt);
    const FloorDesired end = floorDesired(s, t + dt);
    std::array<double, 3> x;
    const auto k1 = floorStateRate<false>(s, state.data(), start);
    for (int i = 0; i < 3; ++i) x[i] = state[i] + 0.5 * dt * k1[i];
    const auto k2 = floorStateRate<false>(s, x.data(), middle);
    for (int i = 0; i < 3; ++i) x[i] = state[i] + 0.5 * dt * k2[i];
    const auto k3 = floorStateRate<false>(s, x.data(), middle);
    for (int i = 0; i < 3; ++i) x[i] = state[i] + dt * k3[i];
    const auto k4 = floorStateRate<false>(s, x.data(), end);
    for (int i = 0; i < 3; ++i) state[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    start = end;
    if (rows_every > 0 && (n + 1) % rows_every == 0) rows((n + 1) * dt, state, start);
  }
  return state;
}

}  // namespace spherical_robots::bench
