// The plant checkpoint (core/plant_checkpoint): every double comes back bit for bit (its sign of
// zero, subnormals, the extremes, infinities, NaN's payload), a write replaces the file whole, and
// a checkpoint of another launch or another model, or a damaged one, is refused with the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/core/loop_timeline.hpp"
#include "spherical_robots/core/plant_checkpoint.hpp"

namespace sr = spherical_robots;

namespace {

std::uint64_t bitsOf(double value) {
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

sr::PlantCheckpoint sample() {
  sr::PlantCheckpoint checkpoint;
  checkpoint.key = {"5f0e2a3c-d0f1-11ee-9a6b-0242ac120002", sr::fingerprintOf("terrain plant 3R")};
  checkpoint.start = 10'000'000;
  checkpoint.time = 31'240'000'000;
  using limits = std::numeric_limits<double>;
  checkpoint.state = {0.1, -0.0, 0.0, 1.0 / 3.0, -2.0438912345678901, limits::denorm_min(),
                      limits::min(), limits::max(), -limits::infinity(), limits::epsilon(),
                      3.0e-300, M_PI};
  return checkpoint;
}

std::string temporaryDirectory() {
  char name[] = "/tmp/test_plant_checkpoint_XXXXXX";
  return mkdtemp(name);
}

}  // namespace

TEST(PlantCheckpoint, RoundTripIsBitExact) {
  const sr::PlantCheckpoint written = sample();
  const sr::PlantCheckpoint read = sr::parsePlantCheckpoint(sr::serialise(written), "text");
  EXPECT_EQ(read.key.run_id, written.key.run_id);
  EXPECT_EQ(read.key.fingerprint, written.key.fingerprint);
  EXPECT_EQ(read.start, written.start);
  EXPECT_EQ(read.time, written.time);
  ASSERT_EQ(read.state.size(), written.state.size());
  for (std::size_t i = 0; i < written.state.size(); ++i)
    EXPECT_EQ(bitsOf(read.state[i]), bitsOf(written.state[i])) << "value " << i << ": "
                                                               << written.state[i];
}

TEST(PlantCheckpoint, NaNComesBackANaN) {
  sr::PlantCheckpoint written = sample();
  written.state = {std::numeric_limits<double>::quiet_NaN()};
  EXPECT_TRUE(std::isnan(sr::parsePlantCheckpoint(sr::serialise(written), "text").state[0]));
}

/// Overwrites `count` bytes of `path` at `offset` with 'x': a slot torn by a kill while written.
void tear(const std::string& path, std::size_t offset, std::size_t count) {
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  file.seekp(static_cast<std::streamoff>(offset));
  file << std::string(count, 'x');
}

sr::PlantCheckpoint at(sr::Nanoseconds time) {
  sr::PlantCheckpoint checkpoint = sample();
  checkpoint.time = time;
  checkpoint.state[0] = 1e-9 * static_cast<double>(time);
  return checkpoint;
}

TEST(PlantCheckpoint, TheNewestCheckpointIsResumed) {
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  sr::PlantCheckpointWriter writer(path);
  for (sr::Nanoseconds t = 10'000'000; t <= 50'000'000; t += 10'000'000) writer.write(at(t));
  const sr::ResumeDecision decision = sr::decideResume(path, sample().key);
  ASSERT_TRUE(decision.checkpoint) << decision.reason;
  EXPECT_EQ(decision.checkpoint->time, 50'000'000);
  EXPECT_EQ(bitsOf(decision.checkpoint->state[0]), bitsOf(at(50'000'000).state[0]));
}

TEST(PlantCheckpoint, ATornSlotFallsBackToTheCheckpointBefore) {
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  {
    sr::PlantCheckpointWriter writer(path);
    writer.write(at(10'000'000));  // slot 1
    writer.write(at(20'000'000));  // slot 2
    writer.write(at(30'000'000));  // slot 1
  }
  tear(path, 100, 20);  // slot 1, in its fingerprint line
  const sr::ResumeDecision decision = sr::decideResume(path, sample().key);
  ASSERT_TRUE(decision.checkpoint) << decision.reason;
  EXPECT_EQ(decision.checkpoint->time, 20'000'000);
  tear(path, sr::kCheckpointSlotSize + 200, 5);  // slot 2 too
  const sr::ResumeDecision none = sr::decideResume(path, sample().key);
  EXPECT_FALSE(none.checkpoint);
  for (const char* needle : {"(slot 1)", "(slot 2)", "checksum does not match"})
    EXPECT_NE(none.reason.find(needle), std::string::npos) << none.reason;
}

TEST(PlantCheckpoint, ARestartedWriterKeepsTheNewestUntilItWritesANewer) {
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  {
    sr::PlantCheckpointWriter writer(path);
    writer.write(at(10'000'000));  // slot 1
    writer.write(at(20'000'000));  // slot 2, the newest
  }
  sr::PlantCheckpointWriter restarted(path);
  restarted.write(at(30'000'000));  // over slot 1, the older
  tear(path, 100, 20);  // slot 1, torn while written
  const sr::ResumeDecision decision = sr::decideResume(path, sample().key);
  ASSERT_TRUE(decision.checkpoint) << decision.reason;
  EXPECT_EQ(decision.checkpoint->time, 20'000'000);
}

TEST(PlantCheckpoint, AStateTooLargeForASlotIsAnErrorNamingTheFile) {
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  sr::PlantCheckpointWriter writer(path);
  sr::PlantCheckpoint large = sample();
  large.state.assign(400, M_PI);
  try {
    writer.write(large);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    for (const std::string& needle : {path, std::string("400 values")})
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(PlantCheckpoint, AnUnwritableDirectoryIsAnErrorNamingTheFile) {
  try {
    sr::PlantCheckpointWriter writer("/nonexistent_directory/plant.checkpoint");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent_directory/plant.checkpoint"),
              std::string::npos) << e.what();
  }
}

TEST(PlantCheckpoint, NoFileMeansStartAfresh) {
  const sr::ResumeDecision decision =
      sr::decideResume(temporaryDirectory() + "/none.checkpoint", sample().key);
  EXPECT_FALSE(decision.checkpoint);
  EXPECT_NE(decision.reason.find("no checkpoint"), std::string::npos) << decision.reason;
}

TEST(PlantCheckpoint, ACheckpointOfAnotherLaunchIsRefusedSayingWhy) {
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  sr::PlantCheckpointWriter(path).write(sample());
  sr::CheckpointKey later_launch = sample().key;
  later_launch.run_id = "7d1c0b9e-d0f1-11ee-9a6b-0242ac120002";
  const sr::ResumeDecision decision = sr::decideResume(path, later_launch);
  EXPECT_FALSE(decision.checkpoint);
  for (const char* needle : {"another launch", "5f0e2a3c-d0f1", "7d1c0b9e-d0f1", path.c_str()})
    EXPECT_NE(decision.reason.find(needle), std::string::npos) << decision.reason;
}

TEST(PlantCheckpoint, ALaterLaunchResumesItsOwnNotAnEarlierOnesNewerCheckpoint) {
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  {
    sr::PlantCheckpointWriter earlier_launch(path);
    earlier_launch.write(at(110'000'000'000));
    earlier_launch.write(at(120'000'000'000));
  }
  sr::PlantCheckpoint own = at(20'000'000'000);
  own.key.run_id = "7d1c0b9e-d0f1-11ee-9a6b-0242ac120002";
  sr::PlantCheckpointWriter(path).write(own);  // over one slot; the other is still 110 s's
  const sr::ResumeDecision decision = sr::decideResume(path, own.key);
  ASSERT_TRUE(decision.checkpoint) << decision.reason;
  EXPECT_EQ(decision.checkpoint->time, own.time);
}

TEST(PlantCheckpoint, ACheckpointOfAnotherModelIsRefusedSayingWhy) {
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  sr::PlantCheckpointWriter(path).write(sample());
  sr::CheckpointKey other_model = sample().key;
  other_model.fingerprint = sr::fingerprintOf("terrain plant RS");
  ASSERT_NE(other_model.fingerprint, sample().key.fingerprint);
  const sr::ResumeDecision decision = sr::decideResume(path, other_model);
  EXPECT_FALSE(decision.checkpoint);
  for (const std::string& needle : {std::string("another model or other parameters"),
                                    sample().key.fingerprint, other_model.fingerprint})
    EXPECT_NE(decision.reason.find(needle), std::string::npos) << decision.reason;
}

TEST(PlantCheckpoint, ADamagedCheckpointIsRefusedNamingTheLine) {
  // Damage that keeps the checksum right: a checkpoint edited by hand.
  const auto resealed = [](std::string body) {
    body = body.substr(0, body.rfind("checksum "));
    return body + "checksum " + sr::fingerprintOf(body) + "\n";
  };
  const std::string text = sr::serialise(sample());
  const std::string body = text.substr(0, text.rfind("checksum "));
  EXPECT_INVALID_ARGUMENT(
      sr::parsePlantCheckpoint(resealed(body.substr(0, body.rfind(' ')) + "\n"), "f.ckpt"),
      "f.ckpt:6", "state of 12 values has 11");
  EXPECT_INVALID_ARGUMENT(sr::parsePlantCheckpoint(resealed("something else\n"), "f.ckpt"),
                          "f.ckpt:1", "not a plant checkpoint");
  std::string bad_time = body;
  bad_time.replace(bad_time.find("time_ns 31240000000"), 19, "time_ns 31.24");
  EXPECT_INVALID_ARGUMENT(sr::parsePlantCheckpoint(resealed(bad_time), "f.ckpt"), "f.ckpt:5",
                          "31.24", "nanoseconds");
  EXPECT_INVALID_ARGUMENT(sr::parsePlantCheckpoint(text.substr(0, 60), "f.ckpt"), "f.ckpt",
                          "no checksum line");
}

TEST(PlantCheckpoint, KeysOfOneRunAndModelMatch) {
  EXPECT_EQ(sr::keyMismatch(sample().key, sample().key), "");
  EXPECT_EQ(sr::fingerprintOf("norma plant"), sr::fingerprintOf("norma plant"));
}

// A resumed timeline goes on as the one that wrote the checkpoint: the next tick advances by one
// step, and the scenario ends at the same time, as a timeline never interrupted.
TEST(LoopTimelineResume, GoesOnAsTheUninterruptedTimeline) {
  constexpr sr::Nanoseconds kStep = 10'000'000;
  sr::LoopTimeline uninterrupted(1.0, sr::kDefaultMaxClockStep);
  sr::LoopTimeline resumed(1.0, sr::kDefaultMaxClockStep);
  sr::Nanoseconds t = kStep;
  for (; t <= 40 * kStep; t += kStep) {
    uninterrupted.tick(t);
    uninterrupted.complete(t);
  }
  resumed.resume(uninterrupted.start(), uninterrupted.lastTick());
  for (; !uninterrupted.finished(); t += kStep) {
    const sr::LoopTimeline::Tick expected = uninterrupted.tick(t);
    const sr::LoopTimeline::Tick got = resumed.tick(t);
    EXPECT_FALSE(got.starts);
    EXPECT_TRUE(got.advances()) << t;
    EXPECT_EQ(got.elapsed, expected.elapsed);
    EXPECT_EQ(resumed.complete(t), uninterrupted.complete(t)) << t;
  }
  EXPECT_TRUE(resumed.finished());
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
