#include "spherical_robots/core/plant_checkpoint.hpp"

#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace spherical_robots {
namespace {

constexpr const char* kHeader = "spherical_robots plant checkpoint 1";

/// The next line, which must be "NAME VALUE"; returns VALUE.
std::string field(std::istream& in, int& line, const std::string& name, const std::string& origin) {
  std::string text;
  ++line;
  if (!std::getline(in, text))
    throw std::invalid_argument(origin + ":" + std::to_string(line) + ": missing '" + name + "'");
  if (text.compare(0, name.size() + 1, name + " ") != 0)
    throw std::invalid_argument(origin + ":" + std::to_string(line) + ": expected '" + name +
                                " ...', got '" + text + "'");
  return text.substr(name.size() + 1);
}

Nanoseconds nanoseconds(const std::string& text, int line, const std::string& origin) {
  std::size_t used = 0;
  try {
    const long long value = std::stoll(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  throw std::invalid_argument(origin + ":" + std::to_string(line) + ": '" + text +
                              "' is not a whole number of nanoseconds");
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
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << std::hash<std::string>{}(description);
  return hex.str();
}

std::string serialise(const PlantCheckpoint& checkpoint) {
  std::ostringstream out;
  out << kHeader << "\nrun_id " << checkpoint.key.run_id << "\nfingerprint "
      << checkpoint.key.fingerprint << "\nstart_ns " << checkpoint.start << "\ntime_ns "
      << checkpoint.time << "\nstate " << checkpoint.state.size();
  // Hexadecimal floating point: every double, its sign of zero and its last bit, back as it was.
  out << std::hexfloat;
  for (const double value : checkpoint.state) out << ' ' << value;
  out << '\n';
  return out.str();
}

PlantCheckpoint parsePlantCheckpoint(const std::string& text, const std::string& origin) {
  std::istringstream in(text);
  std::string header;
  int line = 1;
  if (!std::getline(in, header) || header != kHeader)
    throw std::invalid_argument(origin + ":1: not a plant checkpoint (expected '" +
                                std::string(kHeader) + "')");
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
  const std::string where = origin + ":" + std::to_string(line) + ": ";
  if (!(values >> count)) throw std::invalid_argument(where + "state without its count");
  // strtod, not operator>>: libstdc++'s stream does not read hexadecimal floating point.
  while (values >> word) {
    char* end = nullptr;
    const double value = std::strtod(word.c_str(), &end);
    if (end != word.c_str() + word.size())
      throw std::invalid_argument(where + "'" + word + "' is not a number");
    checkpoint.state.push_back(value);
  }
  if (checkpoint.state.size() != count)
    throw std::invalid_argument(where + "state of " + std::to_string(count) + " values has " +
                                std::to_string(checkpoint.state.size()) + " (a truncated file)");
  return checkpoint;
}

void writePlantCheckpoint(const std::string& path, const PlantCheckpoint& checkpoint) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << serialise(checkpoint);
    if (!out.flush())
      throw std::runtime_error("cannot write the plant checkpoint " + temporary + ": " +
                               std::strerror(errno));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot rename " + temporary + " to " + path + ": " +
                             std::strerror(errno));
}

ResumeDecision decideResume(const std::string& path, const CheckpointKey& current) {
  std::ifstream in(path);
  if (!in) return {std::nullopt, "no checkpoint " + path};
  std::ostringstream text;
  text << in.rdbuf();
  PlantCheckpoint checkpoint;
  try {
    checkpoint = parsePlantCheckpoint(text.str(), path);
  } catch (const std::invalid_argument& e) {
    return {std::nullopt, std::string("the checkpoint cannot be read: ") + e.what()};
  }
  const std::string mismatch = keyMismatch(checkpoint.key, current);
  if (!mismatch.empty()) return {std::nullopt, "the checkpoint " + path + " is refused: " + mismatch};
  return {std::move(checkpoint), {}};
}

void requireStateSize(const std::vector<double>& state, std::size_t size, const std::string& what) {
  if (state.size() != size)
    throw std::invalid_argument("a state of " + what + " has " + std::to_string(size) +
                                " values, the checkpoint's " + std::to_string(state.size()));
}

}  // namespace spherical_robots
