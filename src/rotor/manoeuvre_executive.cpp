#include "spherical_robots/rotor/manoeuvre_executive.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::rotor {
namespace {

const ManoeuvreExecutive::Parameters& validated(const ManoeuvreExecutive::Parameters& p) {
  requirePositive(p.radius, "sphere radius [m]");
  requirePositive(p.inertia_scale, "rotor inertia scale J_zz / J_r");
  requirePositive(p.curve_rate, "curve rate [rad/s]");
  requireAtLeast(p.ramp_time, 0.0, "ramp time [s]");
  requirePositive(p.command_period, "command period [s]");
  requireAtLeast(p.max_rotor_speed, 0.0, "max rotor speed [rad/s]");
  requireAtLeast(p.settle, 0.0, "settle time [s]");
  requireAtLeast(p.actuator_time_constant, 0.0, "actuator time constant [s]");
  requireAtLeast(p.corrections, 0, "corrections");
  requirePositive(p.correction_tolerance, "correction tolerance [m]");
  requirePositive(p.correction_heading_tolerance, "correction heading tolerance [rad]");
  requirePositive(p.correction_tilt_tolerance, "correction tilt tolerance [rad]");
  requireAtLeast(p.correction_steps, 1, "correction steps");
  return p;
}

ManoeuvreExecutive::Report info(std::string text) {
  return {ManoeuvreExecutive::Report::Kind::kInfo, std::move(text)};
}

ManoeuvreExecutive::Report refusal(std::string text) {
  return {ManoeuvreExecutive::Report::Kind::kRefusal, std::move(text)};
}

}  // namespace

const char* toString(ManoeuvreState state) {
  switch (state) {
    case ManoeuvreState::kIdle: return "idle";
    case ManoeuvreState::kExecuting: return "executing";
    case ManoeuvreState::kReturningToPole: return "returning to pole";
    case ManoeuvreState::kCorrecting: return "correcting";
    case ManoeuvreState::kSettling: return "settling";
  }
  return "unknown";
}

const char* toString(ManoeuvreEnd end) {
  switch (end) {
    case ManoeuvreEnd::kExecuted: return "executed";
    case ManoeuvreEnd::kRefused: return "refused";
    case ManoeuvreEnd::kCanceled: return "canceled";
  }
  return "unknown";
}

RestMeasurement measureRest(double centre_x, double centre_y, double radius,
                            const Eigen::Quaterniond& attitude) {
  return {measuredRestPose(centre_x, centre_y, radius, attitude),
          measuredContactAngles(attitude), true};
}

ManoeuvreExecutive::ManoeuvreExecutive(const Parameters& parameters)
    : parameters_(validated(parameters)), clock_(parameters.max_clock_step) {}

void ManoeuvreExecutive::offerPlans(const PlanRequest& request, const PlanResult& result) {
  if (result.solutions.empty()) return;
  plan_k_ = request.k;
  plan_steps_ = request.steps;
  plan_max_radius_ = request.max_radius;
  plans_.clear();
  targets_.clear();
  for (const RotorPlan& solution : result.solutions) {
    plans_.emplace_back(solution.a, solution.b, solution.gamma);
    targets_.push_back({request.u_a, request.v_a, solution.psi});
  }
}

std::string ManoeuvreExecutive::execute(std::uint32_t index) {
  if (executing()) {
    return "plan " + std::to_string(manoeuvre_ ? manoeuvre_->index : *requested_) +
           " is still executing; ignoring execute " + std::to_string(index);
  }
  if (index >= plans_.size()) {
    return "execute " + std::to_string(index) + " refused: the last successful plan request has " +
           std::to_string(plans_.size()) + " solution(s)";
  }
  requested_ = index;
  return {};
}

ManoeuvreVerdict ManoeuvreExecutive::cancel(Nanoseconds now,
                                             const std::optional<RestMeasurement>& measurement) {
  if (!executing()) throw std::logic_error("no execution in progress or requested to cancel");
  stopping_ = true;
  if (manoeuvre_) {
    const ManoeuvreVerdict canceled =
        verdictNow(ManoeuvreEnd::kCanceled, now, measurement, "canceled, the rotors brought to rest");
    manoeuvre_.reset();
    return canceled;
  }
  const std::uint32_t index = *requested_;
  requested_.reset();
  return verdict(ManoeuvreEnd::kCanceled, index, goalOf(index, measurement), 0, 0.0, measurement,
                 "canceled before it started");
}

ManoeuvreExecutive::Output ManoeuvreExecutive::step(
    Nanoseconds now, const std::optional<RestMeasurement>& measurement) {
  Output out;
  followClock(now, out);
  if (requested_) {
    const std::uint32_t index = *requested_;
    requested_.reset();
    begin(index, now, measurement, out);
  } else if (manoeuvre_ && elapsed(now) > manoeuvre_->duration + parameters_.command_period &&
             elapsed(now) >= manoeuvre_->duration + parameters_.settle &&
             !startCorrection(now, measurement, out)) {
    finish(now, measurement, out);
  }
  if (!manoeuvre_) {
    state_ = ManoeuvreState::kIdle;
    if (stopping_) out.set_point = RotorSpeeds{0.0, 0.0};
  } else if (const double t = elapsed(now); t <= manoeuvre_->duration + parameters_.command_period) {
    // One sample past the end: the timing is at rest there, so the last set-point is zero.
    out.set_point = lagCompensatedSetPoint(manoeuvre_->schedule, std::max(t, 0.0),
                                           parameters_.actuator_time_constant,
                                           parameters_.command_period);
    state_ = manoeuvre_->tracing;
  } else {
    state_ = ManoeuvreState::kSettling;
  }
  stopping_ = false;
  out.state = state_;
  if (manoeuvre_) {
    out.progress = ManoeuvreProgress{
        state_, std::clamp(elapsed(now) / manoeuvre_->duration, 0.0, 1.0),
        missFrom(manoeuvre_->goal, measurement), correctionsIn(*manoeuvre_),
        stampSeconds(now - began_)};
  }
  return out;
}

void ManoeuvreExecutive::followClock(Nanoseconds now, Output& out) {
  const ClockStep step = clock_.observe(stampSeconds(now));
  if (step == ClockStep::kJumpForward || step == ClockStep::kJumpBack) {
    out.clock_jump = stampSeconds(now - last_step_);
    if (manoeuvre_) {
      // The schedule goes on from where it was, not from where the jump would put it.
      manoeuvre_->start += now - last_step_;
      began_ += now - last_step_;
      std::ostringstream text;
      text << "time jumped by " << out.clock_jump << " s to " << stampSeconds(now)
           << " s; the manoeuvre continues";
      out.reports.push_back({Report::Kind::kWarning, text.str()});
    }
  }
  last_step_ = now;
}

double ManoeuvreExecutive::elapsed(Nanoseconds now) const {
  return stampSeconds(now - manoeuvre_->start);
}

void ManoeuvreExecutive::begin(std::uint32_t index, Nanoseconds now,
                               const std::optional<RestMeasurement>& measured, Output& out) {
  if (!measured) {
    out.reports.push_back({Report::Kind::kWarning,
                           "no measured rest yet: the goal is the target from the zero state"});
  }
  const RestPose goal = goalOf(index, measured);
  if (startFigureEight(index, plans_[index], plan_steps_, goal, parameters_.corrections,
                       ManoeuvreState::kExecuting, now, out)) {
    ++executions_;
    began_ = now;
  } else {
    out.ended = verdict(ManoeuvreEnd::kRefused, index, goal, 0, 0.0, measured,
                        "not started (" + out.reports.back().text + ")");
  }
}

RestPose ManoeuvreExecutive::goalOf(std::uint32_t index,
                                    const std::optional<RestMeasurement>& measured) const {
  return planEnd(measured ? measured->pose : RestPose{}, targets_[index]);
}

bool ManoeuvreExecutive::startFigureEight(std::uint32_t index, const FigureEight& curve, int steps,
                                          const RestPose& goal, int corrections_left,
                                          ManoeuvreState tracing, Nanoseconds now, Output& out) {
  try {
    const double peak = peakRotorSpeed(plan_k_, parameters_.inertia_scale, curve);
    const double rate = limitedCurveRate(peak, out);
    const CurveTiming timing = curveTiming(steps, rate);
    const double k = plan_k_;
    const double scale = parameters_.inertia_scale;
    manoeuvre_ = Manoeuvre{index,
                           [k, scale, curve, timing](double t) {
                             return planSetPointAt(k, scale, curve, timing, t);
                           },
                           timing.duration(), now, goal, corrections_left, tracing};
    std::ostringstream text;
    text << toString(tracing) << " plan " << index << " (" << steps << " step(s), theta rate "
         << rate << " rad/s, peak rotor speed " << peak * rate << " rad/s) for "
         << timing.duration() << " s";
    out.reports.push_back(info(text.str()));
    return true;
  } catch (const std::invalid_argument& error) {
    out.reports.push_back(refusal("execute " + std::to_string(index) + " refused: " + error.what()));
    return false;
  }
}

void ManoeuvreExecutive::startPoleReturn(const PoleReturnArc& arc, Nanoseconds now, Output& out) {
  const double k = plan_k_;
  const double scale = parameters_.inertia_scale;
  const CurveTiming timing = curveTiming(1, limitedCurveRate(peakRotorSpeed([&](double theta) {
    return arcSetPoint(k, scale, arc, theta, 1.0);
  }), out));
  manoeuvre_->schedule = [k, scale, arc, timing](double t) {
    return arcSetPointAt(k, scale, arc, timing, t);
  };
  manoeuvre_->duration = timing.duration();
  manoeuvre_->start = now;
  manoeuvre_->tracing = ManoeuvreState::kReturningToPole;
}

double ManoeuvreExecutive::limitedCurveRate(double peak_at_unit_rate, Output& out) const {
  const double wanted = parameters_.curve_rate;
  const double limit = parameters_.max_rotor_speed;
  if (limit <= 0.0 || peak_at_unit_rate * wanted <= limit) return wanted;
  // Rotor speeds scale with θ̇ (eq 11 is linear in ω, ω in θ̇: eqs 17-19, 27, 30).
  const double rate = limit / peak_at_unit_rate;
  std::ostringstream text;
  text << "curve rate lowered from " << wanted << " to " << rate << " rad/s: peak rotor speed "
       << peak_at_unit_rate * wanted << " > " << limit << " rad/s";
  out.reports.push_back({Report::Kind::kWarning, text.str()});
  return rate;
}

CurveTiming ManoeuvreExecutive::curveTiming(int steps, double rate) const {
  // Short manoeuvres at high rates shorten the ramps to fit.
  return CurveTiming(steps, rate, std::min(parameters_.ramp_time, 2.0 * M_PI * steps / rate));
}

bool ManoeuvreExecutive::startCorrection(Nanoseconds now,
                                         const std::optional<RestMeasurement>& measured,
                                         Output& out) {
  if (manoeuvre_->corrections_left <= 0) return false;
  if (!measured || !measured->fresh) {
    out.reports.push_back(refusal("no fresh measurement of the rest: no correction from a stale rest"));
    return false;
  }
  try {
    return planCorrection(now, *measured, out);
  } catch (const std::invalid_argument& error) {
    out.reports.push_back(refusal(std::string("no correction: ") + error.what()));
    return false;
  }
}

bool ManoeuvreExecutive::planCorrection(Nanoseconds now, const RestMeasurement& measured,
                                        Output& out) {
  const RestPose goal = manoeuvre_->goal;
  const Miss miss = missFrom(goal, measured);
  const int total = parameters_.corrections;
  const int left = manoeuvre_->corrections_left - 1;
  // First back to the south pole: every figure eight starts and ends there. Never two arcs in a
  // row: an arc that left the contact off the pole was limited by the rotors' noise, which a
  // second one would meet again, while the miss on the plane waits for a figure eight.
  const PoleReturnArc arc(measured.contact_angles.x(), measured.contact_angles.y());
  std::ostringstream text;
  text << miss.distance << " m, " << miss.heading << " rad off the goal";
  if (manoeuvre_->tracing != ManoeuvreState::kReturningToPole &&
      arc.angle() > parameters_.correction_tilt_tolerance) {
    text << ", contact " << arc.angle() << " rad off the south pole: correction " << total - left
         << " of " << total << ", back to the pole";
    out.reports.push_back(info(text.str()));
    startPoleReturn(arc, now, out);
    manoeuvre_->corrections_left = left;
    ++corrections_made_;
    return true;
  }
  if (miss.distance <= parameters_.correction_tolerance &&
      miss.heading <= parameters_.correction_heading_tolerance) {
    return false;
  }
  PlanRequest request;
  request.k = plan_k_;
  request.steps = parameters_.correction_steps;
  request.max_radius = plan_max_radius_;
  const PlanTarget target = correctionTarget(measured.pose, goal);
  request.u_a = target.u_a;
  request.v_a = target.v_a;
  request.psi = target.psi;
  const PlanResult result = planRotorMotion(request);
  if (result.solutions.empty()) {
    out.reports.push_back(refusal(text.str() + ", no correction: " + result.reason));
    return false;
  }
  const RotorPlan& best = result.solutions.front();
  text << ": correction " << total - left << " of " << total << ", a = " << best.a * parameters_.radius
       << " m, b = " << best.b * parameters_.radius << " m";
  out.reports.push_back(info(text.str()));
  if (!startFigureEight(manoeuvre_->index, FigureEight(best.a, best.b, best.gamma),
                        parameters_.correction_steps, goal, left, ManoeuvreState::kCorrecting, now,
                        out)) {
    return false;
  }
  ++corrections_made_;
  return true;
}

void ManoeuvreExecutive::finish(Nanoseconds now, const std::optional<RestMeasurement>& measured,
                                Output& out) {
  out.ended = verdictNow(ManoeuvreEnd::kExecuted, now, measured, "executed");
  out.reports.push_back(info(out.ended->message));
  manoeuvre_.reset();
}

ManoeuvreVerdict ManoeuvreExecutive::verdictNow(ManoeuvreEnd end, Nanoseconds now,
                                                const std::optional<RestMeasurement>& measured,
                                                const std::string& what) {
  return verdict(end, manoeuvre_->index, manoeuvre_->goal, correctionsIn(*manoeuvre_),
                 stampSeconds(now - began_), measured, what);
}

ManoeuvreVerdict ManoeuvreExecutive::verdict(ManoeuvreEnd end, std::uint32_t index,
                                             const RestPose& goal, int corrections,
                                             double elapsed,
                                             const std::optional<RestMeasurement>& measured,
                                             const std::string& what) {
  last_miss_ = missFrom(goal, measured);
  std::ostringstream text;
  text << "plan " << index << " " << what << ", " << last_miss_->distance << " m and "
       << last_miss_->heading << " rad of heading off the goal";
  return {end, index, *last_miss_, corrections, elapsed, text.str()};
}

int ManoeuvreExecutive::correctionsIn(const Manoeuvre& manoeuvre) const {
  return parameters_.corrections - manoeuvre.corrections_left;
}

Miss ManoeuvreExecutive::missFrom(const RestPose& goal,
                                  const std::optional<RestMeasurement>& measured) const {
  const RestPose reached = measured ? measured->pose : RestPose{};
  return {parameters_.radius * std::hypot(goal.u_a - reached.u_a, goal.v_a - reached.v_a),
          std::abs(wrapToPi(goal.psi - reached.psi))};
}

std::string ManoeuvreExecutive::describe() const {
  if (manoeuvre_) {
    return "executing plan " + std::to_string(manoeuvre_->index) + ", " +
           std::to_string(correctionsIn(*manoeuvre_)) + " of " +
           std::to_string(parameters_.corrections) + " corrections";
  }
  if (requested_) return "executing plan " + std::to_string(*requested_) + " from the next step";
  if (stopping_) return "bringing the rotors to rest";
  return plans_.empty() ? "waiting for a plan request" : "idle";
}

}  // namespace spherical_robots::rotor
