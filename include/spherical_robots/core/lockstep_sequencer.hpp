#pragma once
// The decisions of a lock-step barrier (docs/lockstep.md), with time as numbers and no ROS: the
// plant that owns a step asks its participants, one after the other in a fixed order, to do
// their work for the step, and tells each which topics were published since it last worked, so
// that it waits for exactly those messages, whatever order the transport delivers them in. A step
// is done when every participant has acknowledged it or has been dropped for silence.
//
// Step times are integer nanoseconds (ros::Time::toNSec()) so that equality is exact; wall time,
// which only decides timeouts, is seconds.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace spherical_robots {

/// A topic published during the loop, the stamp of its latest message [ns] and the caller id of
/// the node that published it: only that node's messages count as that input, so a stray or
/// hostile message on the topic (one stamped 1,000 s ahead, say) can neither stand in for it
/// nor satisfy every later wait. An empty publisher: any.
struct PublishedTopic {
  std::string topic;
  std::int64_t stamp = 0;
  std::string publisher;
};

/// What the sequencer asks of one participant: work at step time `stamp` [ns], after receiving
/// every message listed in `inputs` (those of its subscriptions among them).
struct StepRequest {
  std::string participant;
  std::int64_t stamp = 0;
  std::vector<PublishedTopic> inputs;
};

enum class AckOutcome {
  kAccepted,   ///< the awaited participant acknowledged the current step
  kForged,     ///< the sender is not the participant the acknowledgement names
  kUnexpected, ///< not awaited now: repeated, out of order, for another step, or unknown sender
};

const char* toString(AckOutcome outcome);

struct ParticipantRecord {
  std::string name;
  bool joined = false;     ///< has asked to join (and was not dropped since)
  std::int64_t next = 0;   ///< [ns] the earliest step it has work at again
  unsigned long acknowledged = 0;
  unsigned long drops = 0;
  std::vector<std::uint64_t> seen;  ///< per topic index: publications it was told of
};

class LockstepSequencer {
 public:
  /// @param owner the sequencing node's caller id (its own finishing request carries it).
  /// @param expected participants in their order of work within a step; others may join and
  /// work after them. @param timeout [s] of wall time > 0 after which an awaited participant is
  /// dropped. @throw std::invalid_argument on a bad timeout or a repeated name.
  LockstepSequencer(std::string owner, std::vector<std::string> expected, double timeout);

  /// A participant asks to (re)join; it works from the next step it is due at. @return true if
  /// it was not a member before (a new or a dropped participant).
  bool join(const std::string& name);
  /// Every expected participant has joined.
  bool allExpectedJoined() const;

  /// Starts the step at `stamp` [ns] after the owner published `published` stamped with it.
  /// @throw std::logic_error if a step is in progress or stamp does not increase.
  void beginStep(std::int64_t stamp, const std::vector<std::string>& published, double wall);
  /// The next request of the step: a due participant, then the owner itself (whose inputs are
  /// what it must receive before the step ends); nullopt once the owner's request was given,
  /// or when no step is in progress. Marks it awaited from `wall`.
  std::optional<StepRequest> nextRequest(double wall);
  /// The participant awaited now, if any (not the owner).
  const std::string* awaited() const;

  /// Whether a message from `sender` (the transport's caller id) may speak for `participant`:
  /// the participant's own, or one from the owner's process, whose caller id the owner's name is
  /// (nodelets in one manager share the manager's caller id).
  bool sentBy(const std::string& sender, const std::string& participant) const;
  /// An acknowledgement from `sender` (the transport's caller id) naming `participant`, forged
  /// unless sentBy(sender, participant). `next` [ns] is when it has work again (0 or less: the
  /// next step).
  AckOutcome acknowledge(const std::string& sender, const std::string& participant,
                         std::int64_t stamp, const std::vector<std::string>& published,
                         std::int64_t next);
  /// Drops the awaited participant if it has been silent for longer than the timeout at `wall`.
  /// @return its name if it was dropped.
  std::optional<std::string> dropSilent(double wall);

  /// The owner's request was handed out: the step is over.
  void endStep();
  bool stepInProgress() const { return in_step_; }
  std::int64_t stamp() const { return stamp_; }
  double timeout() const { return timeout_; }
  const std::vector<ParticipantRecord>& participants() const { return participants_; }
  const std::string& owner() const { return owner_.name; }

 private:
  std::size_t topicIndex(const std::string& topic);
  void record(const std::vector<std::string>& published, const std::string& publisher);
  StepRequest requestFor(ParticipantRecord& participant);

  ParticipantRecord owner_;
  std::vector<ParticipantRecord> participants_;
  std::size_t expected_count_;
  double timeout_;
  std::vector<PublishedTopic> topics_;  ///< every topic published so far: latest stamp, publisher
  std::vector<std::uint64_t> publications_;   ///< per topic: how many times it was published
  bool in_step_ = false;
  bool owner_asked_ = false;
  std::int64_t stamp_ = -1;
  std::size_t cursor_ = 0;                    ///< next participant to consider in this step
  std::optional<std::size_t> awaited_;
  double awaited_since_ = 0.0;
};

}  // namespace spherical_robots
