#include "spherical_robots/core/input_health.hpp"

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots {

const char* toString(HealthLevel level) {
  switch (level) {
    case HealthLevel::kOk: return "OK";
    case HealthLevel::kWarn: return "WARN";
    case HealthLevel::kError: return "ERROR";
  }
  return "?";
}

void validate(const InputHealthPolicy& policy) {
  requirePositive(policy.window, "input health window [s]");
  requirePositive(policy.error_rate, "input health error_rate [1/s]");
  requirePositive(policy.recovery, "input health recovery [s]");
}

InputHealth::InputHealth(InputHealthPolicy policy) : policy_(policy) { validate(policy_); }

void InputHealth::accepted(double t) {
  forgetBefore(t);
  if (rejected_ever_ && t >= last_rejection_) accepted_since_rejection_ = true;
}

void InputHealth::rejected(double t, const std::string& reason) {
  forgetBefore(t);
  recent_rejections_.push_back(t);
  rejected_ever_ = true;
  last_rejection_ = t;
  accepted_since_rejection_ = false;
  last_reason_ = reason;
}

HealthLevel InputHealth::level(double t) {
  forgetBefore(t);
  if (!rejected_ever_) return HealthLevel::kOk;
  if (accepted_since_rejection_ && t - last_rejection_ >= policy_.recovery) {
    return HealthLevel::kOk;
  }
  return rejectionRate(t) > policy_.error_rate ? HealthLevel::kError : HealthLevel::kWarn;
}

double InputHealth::rejectionRate(double t) {
  forgetBefore(t);
  return static_cast<double>(recent_rejections_.size()) / policy_.window;
}

void InputHealth::forgetBefore(double t) {
  if (rejected_ever_ && t < last_rejection_) {
    recent_rejections_.clear();
    rejected_ever_ = false;
    accepted_since_rejection_ = false;
    return;
  }
  while (!recent_rejections_.empty() && recent_rejections_.front() <= t - policy_.window) {
    recent_rejections_.pop_front();
  }
}

}  // namespace spherical_robots
