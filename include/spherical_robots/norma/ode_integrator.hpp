#pragma once
// Integration of Norma's ODEs with Boost.Odeint: an adaptive error-controlled stiff method
// (the closed loop's inner pendulum loop has poles near −100 s⁻¹ and faster), an adaptive
// explicit one, and a fixed-step one for real-time use. No ROS.

#include <boost/numeric/ublas/vector.hpp>
#include <functional>

namespace spherical_robots::norma {

using OdeState = boost::numeric::ublas::vector<double>;
/// dx/dt = f(x, t).
using OdeRhs = std::function<void(const OdeState& x, OdeState& dxdt, double t)>;
/// Called with the state at each logging time t.
using OdeObserver = std::function<void(const OdeState& x, double t)>;

enum class OdeMethod {
  kRosenbrock4,  ///< adaptive, L-stable, 4th order, finite-difference Jacobian: the default
  kDopri5,       ///< adaptive explicit Dormand-Prince 5(4); step bounded by the fastest pole
  kFixedRk4,     ///< classical Runge-Kutta with a fixed step, no error control
};

struct OdeOptions {
  OdeMethod method = OdeMethod::kRosenbrock4;
  double rtol = 1e-3;         ///< relative tolerance (adaptive methods)
  double atol = 1e-6;         ///< absolute tolerance (adaptive methods)
  double initial_step = 1e-3; ///< first step [s] of the adaptive methods
  double fixed_step = 1e-3;   ///< step [s] of kFixedRk4
};

/// @throw std::invalid_argument naming the first option that is not finite and > 0.
void validate(const OdeOptions& options);

/// The most samples one logged run may ask for (a 1300 s run at the paper's rate logs 1.3e4).
constexpr double kMaxLoggedSamples = 1e8;

/// Integrates x from t = 0 to duration, calling observer at t = k / log_rate for every k with
/// k / log_rate <= duration (t = 0 and, when it falls on the grid, t = duration inclusive; a
/// final call at t = duration otherwise). x holds the state at t = duration on return.
/// @throw std::invalid_argument on duration < 0, a log rate or option that is not > 0, more than
///        kMaxLoggedSamples samples, or a state that turns non-finite.
void integrateLogged(const OdeRhs& rhs, OdeState& x, double duration, double log_rate,
                     const OdeOptions& options, const OdeObserver& observer);

}  // namespace spherical_robots::norma
