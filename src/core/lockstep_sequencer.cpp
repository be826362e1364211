#include "spherical_robots/core/lockstep_sequencer.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace spherical_robots {

const char* toString(AckOutcome outcome) {
  switch (outcome) {
    case AckOutcome::kAccepted: return "accepted";
    case AckOutcome::kForged: return "forged";
    case AckOutcome::kUnexpected: return "unexpected";
  }
  return "?";
}

LockstepSequencer::LockstepSequencer(std::string owner, std::vector<std::string> expected,
                                     double timeout)
    : expected_count_(expected.size()), timeout_(timeout) {
  if (!(timeout > 0.0) || !std::isfinite(timeout)) {
    std::ostringstream what;
    what << "lock-step timeout = " << timeout << " s must be finite and > 0";
    throw std::invalid_argument(what.str());
  }
  owner_.name = std::move(owner);
  owner_.joined = true;
  for (std::string& name : expected) {
    const bool repeated = std::any_of(participants_.begin(), participants_.end(),
                                      [&](const ParticipantRecord& p) { return p.name == name; });
    if (repeated || name == owner_.name)
      throw std::invalid_argument("lock-step participant " + name + " is listed twice");
    ParticipantRecord participant;
    participant.name = std::move(name);
    participants_.push_back(std::move(participant));
  }
}

bool LockstepSequencer::join(const std::string& name) {
  if (name == owner_.name) return false;
  auto it = std::find_if(participants_.begin(), participants_.end(),
                         [&](const ParticipantRecord& p) { return p.name == name; });
  if (it == participants_.end()) {
    ParticipantRecord participant;
    participant.name = name;
    participants_.push_back(std::move(participant));
    it = participants_.end() - 1;
  }
  if (it->joined) return false;
  it->joined = true;
  it->next = 0;
  // It starts from what is published from now on: it cannot have received anything older.
  it->seen = publications_;
  return true;
}

bool LockstepSequencer::allExpectedJoined() const {
  return std::all_of(participants_.begin(), participants_.begin() + expected_count_,
                     [](const ParticipantRecord& p) { return p.joined; });
}

std::size_t LockstepSequencer::topicIndex(const std::string& topic) {
  for (std::size_t i = 0; i < topics_.size(); ++i)
    if (topics_[i].topic == topic) return i;
  topics_.push_back({topic, 0, {}});
  publications_.push_back(0);
  return topics_.size() - 1;
}

void LockstepSequencer::record(const std::vector<std::string>& published,
                               const std::string& publisher) {
  for (const std::string& topic : published) {
    const std::size_t i = topicIndex(topic);
    topics_[i].stamp = stamp_;
    topics_[i].publisher = publisher;
    ++publications_[i];
  }
}

void LockstepSequencer::beginStep(std::int64_t stamp, const std::vector<std::string>& published,
                                  double wall) {
  if (in_step_) throw std::logic_error("lock-step: a step began before the last one ended");
  if (stamp <= stamp_) {
    std::ostringstream what;
    what << "lock-step: step time " << stamp << " ns does not follow " << stamp_ << " ns";
    throw std::logic_error(what.str());
  }
  stamp_ = stamp;
  in_step_ = true;
  owner_asked_ = false;
  cursor_ = 0;
  awaited_.reset();
  awaited_since_ = wall;
  record(published, owner_.name);
}

StepRequest LockstepSequencer::requestFor(ParticipantRecord& participant) {
  StepRequest request;
  request.participant = participant.name;
  request.stamp = stamp_;
  participant.seen.resize(publications_.size(), 0);
  for (std::size_t i = 0; i < topics_.size(); ++i) {
    if (publications_[i] > participant.seen[i]) request.inputs.push_back(topics_[i]);
    participant.seen[i] = publications_[i];
  }
  return request;
}

std::optional<StepRequest> LockstepSequencer::nextRequest(double wall) {
  if (!in_step_ || awaited_ || owner_asked_) return std::nullopt;
  while (cursor_ < participants_.size()) {
    const std::size_t i = cursor_++;
    ParticipantRecord& participant = participants_[i];
    if (!participant.joined || participant.next > stamp_) continue;
    awaited_ = i;
    awaited_since_ = wall;
    return requestFor(participant);
  }
  owner_asked_ = true;
  return requestFor(owner_);
}

const std::string* LockstepSequencer::awaited() const {
  return awaited_ ? &participants_[*awaited_].name : nullptr;
}

bool LockstepSequencer::sentBy(const std::string& sender, const std::string& participant) const {
  return sender == participant || sender == owner_.name;
}

AckOutcome LockstepSequencer::acknowledge(const std::string& sender, const std::string& participant,
                                          std::int64_t stamp, const std::vector<std::string>& published,
                                          std::int64_t next) {
  if (!sentBy(sender, participant)) return AckOutcome::kForged;
  if (!awaited_ || participants_[*awaited_].name != participant || stamp != stamp_)
    return AckOutcome::kUnexpected;
  ParticipantRecord& record_of = participants_[*awaited_];
  ++record_of.acknowledged;
  record_of.next = next;
  record(published, sender);
  // What it published itself is nothing new to it.
  record_of.seen.resize(publications_.size(), 0);
  for (const std::string& topic : published) record_of.seen[topicIndex(topic)] = publications_[topicIndex(topic)];
  awaited_.reset();
  return AckOutcome::kAccepted;
}

std::optional<std::string> LockstepSequencer::dropSilent(double wall) {
  if (!awaited_ || wall - awaited_since_ <= timeout_) return std::nullopt;
  ParticipantRecord& participant = participants_[*awaited_];
  participant.joined = false;
  ++participant.drops;
  awaited_.reset();
  return participant.name;
}

void LockstepSequencer::endStep() { in_step_ = false; }

}  // namespace spherical_robots
