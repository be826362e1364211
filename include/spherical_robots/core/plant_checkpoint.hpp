#pragma once
// What a restarted plant resumes from (no ROS): its last published state, with the scenario's
// start and the state's time, written atomically at each publication and read back bit for bit.
// A checkpoint belongs to one launch (roslaunch's /run_id, which a respawned node sees again and
// a new launch does not) and to one model with its parameters (a fingerprint): one of another
// run or another model is refused, with the reason, and the plant starts afresh
// (docs/conventions.md, "When a node dies").

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

/// A short, stable digest of a model's description (its kind and parameters as text).
std::string fingerprintOf(const std::string& description);

struct PlantCheckpoint {
  CheckpointKey key;
  Nanoseconds start = 0;      ///< the scenario's first tick
  Nanoseconds time = 0;       ///< the state's
  std::vector<double> state;  ///< as the plant serialises its model's state
};

/// The checkpoint as text; parsePlantCheckpoint gives back every double bit for bit.
std::string serialise(const PlantCheckpoint& checkpoint);

/// @param origin names the text in errors (the file). @throw std::invalid_argument naming origin,
///        the line and the problem.
PlantCheckpoint parsePlantCheckpoint(const std::string& text, const std::string& origin);

/// Writes `path` atomically (a temporary beside it, then a rename): a process killed while writing
/// leaves the previous checkpoint whole. @throw std::runtime_error naming the file and the error.
void writePlantCheckpoint(const std::string& path, const PlantCheckpoint& checkpoint);

/// Whether a plant starting under `current` resumes from `path`: the checkpoint, or none and why
/// (no file, unreadable, of another run or model, started at t = 0).
struct ResumeDecision {
  std::optional<PlantCheckpoint> checkpoint;
  std::string reason;  ///< why not; empty when resuming
};
ResumeDecision decideResume(const std::string& path, const CheckpointKey& current);

/// @throw std::invalid_argument unless `state` has `size` values, naming the model (`what`).
void requireStateSize(const std::vector<double>& state, std::size_t size, const std::string& what);

}  // namespace spherical_robots
