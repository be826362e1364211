#pragma once
// What a restarted plant resumes from (no ROS): its last published state, with the scenario's
// start and the state's time, written at each publication and read back bit for bit. A checkpoint
// belongs to one launch (roslaunch's /run_id, which a respawned node sees again and a new launch
// does not) and to one model with its parameters (a fingerprint): one of another run or another
// model is refused, with the reason, and the plant starts afresh (docs/conventions.md, "When a
// node dies").
//
// The file holds two slots of kCheckpointSlotSize bytes, written in turn, each in one pwrite over
// the older one: a plant writes at every step (1 kHz for Norma), where a temporary file and a
// rename cost 0.2-0.6 ms on a loaded machine and a pwrite 3 us. A slot torn by a kill while it
// was written fails its checksum, and the other slot, one publication older, is resumed.

#include <optional>
#include <string>
#include <vector>

#include "spherical_robots/core/stamp.hpp"

namespace spherical_robots {

/// Whose a checkpoint (or any state kept across a restart) is.
struct CheckpointKey {
  std::string run_id;       ///< roslaunch's /run_id
  std::string fingerprint;  ///< of the model and its parameters (fingerprintOf)
};

/// Why state kept under `stored` may not be taken up by a node under `current`; empty if it may.
std::string keyMismatch(const CheckpointKey& stored, const CheckpointKey& current);

/// A short, stable digest of a text (a model's kind and parameters; a checkpoint's contents).
std::string fingerprintOf(const std::string& description);

struct PlantCheckpoint {
  CheckpointKey key;
  Nanoseconds start = 0;      ///< the scenario's first tick
  Nanoseconds time = 0;       ///< the state's
  std::vector<double> state;  ///< as the plant serialises its model's state
};

/// [bytes] of one slot of a checkpoint file: a state of up to about 150 doubles.
constexpr std::size_t kCheckpointSlotSize = 4096;

/// The checkpoint as text, ending in a checksum line; parsePlantCheckpoint gives back every
/// double bit for bit (hexadecimal floating point).
std::string serialise(const PlantCheckpoint& checkpoint);

/// @param origin names the text in errors (the file and slot). @throw std::invalid_argument
///        naming origin, the line and the problem (a checksum that does not match: a torn write).
PlantCheckpoint parsePlantCheckpoint(const std::string& text, const std::string& origin);

/// Writes a plant's checkpoints to one file, over its older slot each time.
class PlantCheckpointWriter {
 public:
  /// Opens (creates) `path`; an existing file's newer slot is kept until a newer checkpoint is
  /// written. @throw std::runtime_error naming the file and the error.
  explicit PlantCheckpointWriter(std::string path);
  ~PlantCheckpointWriter();
  PlantCheckpointWriter(const PlantCheckpointWriter&) = delete;
  PlantCheckpointWriter& operator=(const PlantCheckpointWriter&) = delete;

  /// @throw std::runtime_error naming the file and the error (also a state too large for a slot).
  void write(const PlantCheckpoint& checkpoint);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
  int next_slot_ = 0;
};

/// Whether a plant starting under `current` resumes from the file `path`: its newest intact
/// checkpoint, or none and why (no file, no intact slot, of another run or model).
struct ResumeDecision {
  std::optional<PlantCheckpoint> checkpoint;
  std::string reason;  ///< why not; empty when resuming
};
ResumeDecision decideResume(const std::string& path, const CheckpointKey& current);

/// @throw std::invalid_argument unless `state` has `size` values, naming the model (`what`).
void requireStateSize(const std::vector<double>& state, std::size_t size, const std::string& what);

}  // namespace spherical_robots
