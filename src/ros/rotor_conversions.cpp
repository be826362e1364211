#include "spherical_robots/ros/rotor_conversions.hpp"

#include <cstdint>

namespace spherical_robots::conversions {
namespace {

using Result = spherical_robots::ExecuteRotorManoeuvreResult;

std::uint8_t statusOf(rotor::ManoeuvreEnd end) {
  switch (end) {
    case rotor::ManoeuvreEnd::kExecuted: return Result::EXECUTED;
    case rotor::ManoeuvreEnd::kRefused: return Result::ABORTED;
    case rotor::ManoeuvreEnd::kCanceled: return Result::PREEMPTED;
  }
  return Result::ABORTED;
}

}  // namespace

Result toManoeuvreResult(const rotor::ManoeuvreVerdict& verdict) {
  Result result;
  result.status = statusOf(verdict.end);
  result.distance = verdict.miss.distance;
  result.heading_error = verdict.miss.heading;
  result.corrections = static_cast<std::uint32_t>(verdict.corrections);
  result.elapsed = verdict.elapsed;
  result.message = verdict.message;
  return result;
}

Result rejectedManoeuvreResult(const std::string& why) {
  Result result;
  result.status = Result::REJECTED;
  result.message = why;
  return result;
}

spherical_robots::ExecuteRotorManoeuvreFeedback toManoeuvreFeedback(
    const rotor::ManoeuvreProgress& progress) {
  spherical_robots::ExecuteRotorManoeuvreFeedback feedback;
  feedback.state = rotor::toString(progress.state);
  feedback.progress = progress.fraction;
  feedback.distance = progress.miss.distance;
  feedback.heading_error = progress.miss.heading;
  feedback.corrections = static_cast<std::uint32_t>(progress.corrections);
  feedback.elapsed = progress.elapsed;
  return feedback;
}

}  // namespace spherical_robots::conversions
