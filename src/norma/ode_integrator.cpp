#include "spherical_robots/norma/ode_integrator.hpp"

#include <boost/numeric/odeint.hpp>
#include <boost/numeric/ublas/matrix.hpp>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::norma {
namespace odeint = boost::numeric::odeint;
namespace {

using OdeMatrix = boost::numeric::ublas::matrix<double>;

// Logging may be sparse (1 Hz) against millisecond steps; the checker only guards against a
// stalled integration.
constexpr int kMaxStepsBetweenLogs = 100000000;

std::vector<double> logTimes(double duration, double log_rate) {
  std::vector<double> times;
  const auto last = static_cast<long>(std::floor(duration * log_rate + 1e-9));
  times.reserve(static_cast<std::size_t>(last) + 2);
  for (long k = 0; k <= last; ++k) times.push_back(std::min(duration, k / log_rate));
  if (duration - times.back() > 1e-9 * std::max(1.0, duration)) times.push_back(duration);
  return times;
}

// Forward differences (relative step √ε) in x and t. Rosenbrock's order assumes the exact
// Jacobian; these are good to about 1e-8 relative, which is harmless at the tolerances this
// method is meant for but makes it crawl near rtol 1e-10 (use kDopri5 there).
struct FiniteDifferenceJacobian {
  const OdeRhs* rhs;
  void operator()(const OdeState& x, OdeMatrix& jac, double t, OdeState& dfdt) const {
    const std::size_t n = x.size();
    OdeState f0(n), f1(n), xp = x;
    (*rhs)(x, f0, t);
    const double root_eps = std::sqrt(std::numeric_limits<double>::epsilon());
    for (std::size_t j = 0; j < n; ++j) {
      const double h = root_eps * std::max(1.0, std::abs(x[j]));
      xp[j] = x[j] + h;
      (*rhs)(xp, f1, t);
      xp[j] = x[j];
      for (std::size_t i = 0; i < n; ++i) jac(i, j) = (f1[i] - f0[i]) / h;
    }
    const double ht = root_eps * std::max(1.0, std::abs(t));
    (*rhs)(x, f1, t + ht);
    for (std::size_t i = 0; i < n; ++i) dfdt[i] = (f1[i] - f0[i]) / ht;
  }
};

}  // namespace

void validate(const OdeOptions& options) {
  requireAllPositive({{options.rtol, "rtol"},
                      {options.atol, "atol"},
                      {options.initial_step, "initial step [s]"},
                      {options.fixed_step, "fixed step [s]"}});
}

void integrateLogged(const OdeRhs& rhs, OdeState& x, double duration, double log_rate,
                     const OdeOptions& options, const OdeObserver& observer) {
  validate(options);
  requireFinite(duration, "duration [s]");
  if (duration < 0.0) {
    throw std::invalid_argument("duration [s] must be >= 0, got " + std::to_string(duration));
  }
  requirePositive(log_rate, "log rate [Hz]");
  // Bounded before anything is allocated: 1e300 s at 1 Hz is a request, not a run.
  if (!(duration * log_rate <= kMaxLoggedSamples)) {
    std::ostringstream message;
    message << "duration " << duration << " s at log rate " << log_rate << " Hz is "
            << duration * log_rate << " samples, more than the " << kMaxLoggedSamples
            << " a run allows";
    throw std::invalid_argument(message.str());
  }
  const std::vector<double> times = logTimes(duration, log_rate);
  auto checked_observer = [&observer](const OdeState& state, double t) {
    for (double v : state) {
      if (!std::isfinite(v)) {
        throw std::invalid_argument("the state became non-finite at t = " + std::to_string(t) +
                                    " s");
      }
    }
    observer(state, t);
  };
  auto system = [&rhs](const OdeState& state, OdeState& dxdt, double t) { rhs(state, dxdt, t); };
  const odeint::max_step_checker checker(kMaxStepsBetweenLogs);
  switch (options.method) {
    case OdeMethod::kRosenbrock4:
      odeint::integrate_times(
          odeint::make_dense_output(options.atol, options.rtol, odeint::rosenbrock4<double>()),
          std::make_pair(system, FiniteDifferenceJacobian{&rhs}), x, times.begin(), times.end(),
          options.initial_step, checked_observer, checker);
      break;
    case OdeMethod::kDopri5:
      odeint::integrate_times(
          odeint::make_dense_output(options.atol, options.rtol,
                                    odeint::runge_kutta_dopri5<OdeState>()),
          system, x, times.begin(), times.end(), options.initial_step, checked_observer, checker);
      break;
    case OdeMethod::kFixedRk4:
      odeint::integrate_times(odeint::runge_kutta4<OdeState>(), system, x, times.begin(),
                              times.end(), options.fixed_step, checked_observer, checker);
      break;
  }
}

}  // namespace spherical_robots::norma
