#include "spherical_robots/core/plant_checkpoint.hpp"

#include <boost/crc.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace spherical_robots {
namespace {

constexpr const char* kHeader = "spherical_robots plant checkpoint 2";
constexpr const char* kChecksum = "checksum ";

std::string lineAt(const std::string& origin, int line) {
  return origin + ":" + std::to_string(line) + ": ";
}

/// The next line, which must be "NAME VALUE"; returns VALUE.
std::string field(std::istream& in, int& line, const std::string& name, const std::string& origin) {
  std::string text;
  ++line;
  if (!std::getline(in, text))
    throw std::invalid_argument(lineAt(origin, line) + "missing '" + name + "'");
  if (text.compare(0, name.size() + 1, name + " ") != 0)
    throw std::invalid_argument(lineAt(origin, line) + "expected '" + name + " ...', got '" +
                                text + "'");
  return text.substr(name.size() + 1);
}

Nanoseconds nanoseconds(const std::string& text, int line, const std::string& origin) {
  std::size_t used = 0;
  try {
    const long long value = std::stoll(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument(lineAt(origin, line) + "'" + text +
                              "' is not a whole number of nanoseconds");
}

[[noreturn]] void throwSystemError(const std::string& what, const std::string& path) {
  throw std::runtime_error("cannot " + what + " the plant checkpoint " + path + ": " +
                           std::strerror(errno));
}

/// The slots' texts (up to their padding) of a checkpoint file's contents.
std::vector<std::string> slotsOf(const std::string& contents) {
  std::vector<std::string> slots;
  for (std::size_t at = 0; at < contents.size(); at += kCheckpointSlotSize) {
    const std::string slot = contents.substr(at, kCheckpointSlotSize);
    slots.push_back(slot.substr(0, slot.find('\0')));
  }
  return slots;
}

/// The newest intact checkpoint of a file's contents (of `key`'s run and model, if given: the
/// other slot may still hold one of an earlier launch), or why there is none.
std::optional<PlantCheckpoint> newestOf(const std::string& contents, const std::string& path,
                                        std::string& reason, int* slot_index = nullptr,
                                        const CheckpointKey* key = nullptr) {
  std::optional<PlantCheckpoint> newest;
  const std::vector<std::string> slots = slotsOf(contents);
  for (std::size_t i = 0; i < slots.size(); ++i) {
    if (slots[i].empty()) continue;  // never written
    try {
      PlantCheckpoint checkpoint =
          parsePlantCheckpoint(slots[i], path + " (slot " + std::to_string(i + 1) + ")");
      if (key) {
        const std::string mismatch = keyMismatch(checkpoint.key, *key);
        if (!mismatch.empty()) {
          reason += std::string(reason.empty() ? "" : "; ") + path + " (slot " +
                    std::to_string(i + 1) + ") is refused: " + mismatch;
          continue;
        }
      }
      if (!newest || checkpoint.time > newest->time) {
        newest = std::move(checkpoint);
        if (slot_index) *slot_index = static_cast<int>(i);
      }
    } catch (const std::invalid_argument& e) {
      reason += std::string(reason.empty() ? "" : "; ") + e.what();
    }
  }
  if (!newest && reason.empty()) reason = path + " holds no checkpoint";
  return newest;
}

std::string contentsOf(std::ifstream& in) {
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

std::string keyMismatch(const CheckpointKey& stored, const CheckpointKey& current) {
  if (stored.run_id != current.run_id)
    return "it is of another launch (run_id " + stored.run_id + ", this launch's " +
           current.run_id + ")";
  if (stored.fingerprint != current.fingerprint)
    return "it is of another model or other parameters (fingerprint " + stored.fingerprint +
           ", this node's " + current.fingerprint + ")";
  return {};
}

std::string fingerprintOf(const std::string& description) {
  // CRC-32 (Boost.CRC): defined bit for bit, unlike std::hash, whose value is the library's.
  boost::crc_32_type crc;
  crc.process_bytes(description.data(), description.size());
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(crc.checksum()));
  return hex;
}

std::string serialise(const PlantCheckpoint& checkpoint) {
  std::string text = std::string(kHeader) + "\nrun_id " + checkpoint.key.run_id +
                     "\nfingerprint " + checkpoint.key.fingerprint + "\nstart_ns " +
                     std::to_string(checkpoint.start) + "\ntime_ns " +
                     std::to_string(checkpoint.time) + "\nstate " +
                     std::to_string(checkpoint.state.size());
  // Hexadecimal floating point: every double, its sign of zero and its last bit, back as it was.
  char value[40];
  for (const double x : checkpoint.state) {
    std::snprintf(value, sizeof value, " %a", x);
    text += value;
  }
  text += '\n';
  return text + kChecksum + fingerprintOf(text) + '\n';
}

PlantCheckpoint parsePlantCheckpoint(const std::string& text, const std::string& origin) {
  const std::size_t checksum_at = text.rfind(kChecksum);
  if (checksum_at == std::string::npos || (checksum_at > 0 && text[checksum_at - 1] != '\n'))
    throw std::invalid_argument(origin + ": no checksum line (a torn or truncated write)");
  const std::string body = text.substr(0, checksum_at);
  if (text.substr(checksum_at) != kChecksum + fingerprintOf(body) + '\n')
    throw std::invalid_argument(origin + ": the checksum does not match (a torn write)");
  std::istringstream in(body);
  std::string header;
  int line = 1;
  if (!std::getline(in, header) || header != kHeader)
    throw std::invalid_argument(lineAt(origin, 1) + "not a plant checkpoint (expected '" +
                                kHeader + "')");
  PlantCheckpoint checkpoint;
  checkpoint.key.run_id = field(in, line, "run_id", origin);
  checkpoint.key.fingerprint = field(in, line, "fingerprint", origin);
  const std::string start = field(in, line, "start_ns", origin);
  checkpoint.start = nanoseconds(start, line, origin);
  const std::string time = field(in, line, "time_ns", origin);
  checkpoint.time = nanoseconds(time, line, origin);
  std::istringstream values(field(in, line, "state", origin));
  std::size_t count = 0;
  std::string word;
  if (!(values >> count)) throw std::invalid_argument(lineAt(origin, line) + "state without its count");
  // strtod, not operator>>: libstdc++'s stream does not read hexadecimal floating point.
  while (values >> word) {
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (end != word.c_str() + word.size())
      throw std::invalid_argument(lineAt(origin, line) + "'" + word + "' is not a number");
    checkpoint.state.push_back(value);
  }
  if (checkpoint.state.size() != count)
    throw std::invalid_argument(lineAt(origin, line) + "state of " + std::to_string(count) +
                                " values has " + std::to_string(checkpoint.state.size()));
  return checkpoint;
}

PlantCheckpointWriter::PlantCheckpointWriter(std::string path) : path_(std::move(path)) {
  // The slot after the newest intact one, so that it is overwritten only by a newer checkpoint.
  int newest_slot = 1;
  if (std::ifstream in{path_, std::ios::binary}) {
    std::string ignored;
    newestOf(contentsOf(in), path_, ignored, &newest_slot);
  }
  next_slot_ = 1 - newest_slot;
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throwSystemError("open", path_);
}

PlantCheckpointWriter::~PlantCheckpointWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void PlantCheckpointWriter::write(const PlantCheckpoint& checkpoint) {
  std::string slot = serialise(checkpoint);
  if (slot.size() >= kCheckpointSlotSize)
    throw std::runtime_error("the plant checkpoint " + path_ + ": a state of " +
                             std::to_string(checkpoint.state.size()) + " values takes " +
                             std::to_string(slot.size()) + " bytes, more than a slot's " +
                             std::to_string(kCheckpointSlotSize));
  slot.resize(kCheckpointSlotSize, '\0');
  const off_t offset = static_cast<off_t>(next_slot_) * static_cast<off_t>(kCheckpointSlotSize);
  if (::pwrite(fd_, slot.data(), slot.size(), offset) != static_cast<ssize_t>(slot.size()))
    throwSystemError("write", path_);
  next_slot_ = 1 - next_slot_;
}

ResumeDecision decideResume(const std::string& path, const CheckpointKey& current) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {std::nullopt, "no checkpoint " + path};
  std::string reason;
  std::optional<PlantCheckpoint> newest = newestOf(contentsOf(in), path, reason, nullptr, &current);
  if (!newest) return {std::nullopt, "no checkpoint of this run: " + reason};
  return {std::move(newest), {}};
}

void requireStateSize(const std::vector<double>& state, std::size_t size, const std::string& what) {
  if (state.size() != size)
    throw std::invalid_argument("a state of " + what + " has " + std::to_string(size) +
                                " values, the checkpoint's " + std::to_string(state.size()));
}

}  // namespace spherical_robots
