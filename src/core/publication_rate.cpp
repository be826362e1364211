#include "spherical_robots/core/publication_rate.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spherical_robots {

PublicationRate::PublicationRate(double target, double tolerance, std::size_t reports)
    : target_(target), tolerance_(tolerance), reports_(reports) {
  std::ostringstream problem;
  if (!(std::isfinite(target) && target > 0.0))
    problem << "target rate " << target << " Hz: must be finite and > 0";
  else if (!(tolerance >= 0.0 && tolerance < 1.0))
    problem << "rate tolerance " << tolerance << ": must be in [0, 1)";
  else if (reports < 1)
    problem << "window of " << reports << " reports: must be >= 1";
  if (!problem.str().empty()) throw std::invalid_argument(problem.str());
}

PublicationRate::Report PublicationRate::restart(Nanoseconds now, const std::string& why,
                                                 bool measure) {
  marks_.clear();
  if (measure) marks_.push_back({now, total_});
  Report report;
  report.message = why;
  report.total = total_;
  return report;
}

PublicationRate::Report PublicationRate::report(Nanoseconds now, bool expected) {
  const std::optional<Nanoseconds> last = last_report_;
  last_report_ = now;
  // Not measured through an idle spell: its silence is not the node's.
  if (!expected) return restart(now, "idle: nothing to publish", false);
  if (last && now == *last)
    return restart(now, "time stands still (not started, paused or ended)", true);
  if (last && now < *last) return restart(now, "time went back: measuring afresh", true);
  if (marks_.empty()) return restart(now, "measuring", true);

  const Mark oldest = marks_.front();
  Report report;
  report.events = total_ - oldest.total;
  report.total = total_;
  report.window = stampSeconds(now - oldest.time);
  report.frequency = static_cast<double>(report.events) / report.window;
  marks_.push_back({now, total_});
  if (marks_.size() > reports_) marks_.pop_front();

  std::ostringstream message;
  if (report.events == 0) {
    report.level = HealthLevel::kError;
    message << "nothing published in " << report.window << " s";
  } else if (*report.frequency < target_ * (1.0 - tolerance_) ||
             *report.frequency > target_ * (1.0 + tolerance_)) {
    report.level = HealthLevel::kWarn;
    message << "rate too " << (*report.frequency < target_ ? "low" : "high") << ": "
            << *report.frequency << " Hz, configured " << target_ << " Hz +- "
            << tolerance_ * 100.0 << " %";
  } else {
    message << "at the configured rate";
  }
  report.message = message.str();
  return report;
}

}  // namespace spherical_robots
