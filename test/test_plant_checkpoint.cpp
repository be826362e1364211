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

TEST(PlantCheckpoint, WriteReplacesTheFileAndLeavesNoTemporary) {
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  sr::PlantCheckpoint first = sample();
  sr::writePlantCheckpoint(path, first);
  sr::PlantCheckpoint second = sample();
  second.time += 10'000'000;
  second.state[0] = 0.2;
  sr::writePlantCheckpoint(path, second);
  const sr::ResumeDecision decision = sr::decideResume(path, second.key);
  ASSERT_TRUE(decision.checkpoint) << decision.reason;
  EXPECT_EQ(decision.checkpoint->time, second.time);
  EXPECT_EQ(bitsOf(decision.checkpoint->state[0]), bitsOf(0.2));
  EXPECT_FALSE(std::ifstream(path + ".tmp"));
}

TEST(PlantCheckpoint, AnUnwritableDirectoryIsAnErrorNamingTheFile) {
  try {
    sr::writePlantCheckpoint("/nonexistent_directory/plant.checkpoint", sample());
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
  sr::writePlantCheckpoint(path, sample());
  sr::CheckpointKey later_launch = sample().key;
  later_launch.run_id = "7d1c0b9e-d0f1-11ee-9a6b-0242ac120002";
  const sr::ResumeDecision decision = sr::decideResume(path, later_launch);
  EXPECT_FALSE(decision.checkpoint);
  for (const char* needle : {"another launch", "5f0e2a3c-d0f1", "7d1c0b9e-d0f1", path.c_str()})
    EXPECT_NE(decision.reason.find(needle), std::string::npos) << decision.reason;
}

TEST(PlantCheckpoint, ACheckpointOfAnotherModelIsRefusedSayingWhy) {
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  sr::writePlantCheckpoint(path, sample());
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
  const std::string text = sr::serialise(sample());
  // Cut inside the state's values: a checkpoint written by something other than
  // writePlantCheckpoint, whose rename never leaves half a file.
  EXPECT_INVALID_ARGUMENT(sr::parsePlantCheckpoint(text.substr(0, text.rfind(' ')) + "\n", "f.ckpt"),
                          "f.ckpt:6", "truncated");
  EXPECT_INVALID_ARGUMENT(sr::parsePlantCheckpoint("something else\n", "f.ckpt"), "f.ckpt:1",
                          "not a plant checkpoint");
  std::string bad_time = text;
  bad_time.replace(bad_time.find("time_ns 31240000000"), 19, "time_ns 31.24");
  EXPECT_INVALID_ARGUMENT(sr::parsePlantCheckpoint(bad_time, "f.ckpt"), "f.ckpt:5", "31.24",
                          "nanoseconds");
  const std::string path = temporaryDirectory() + "/plant.checkpoint";
  std::ofstream(path) << text.substr(0, 60);
  const sr::ResumeDecision decision = sr::decideResume(path, sample().key);
  EXPECT_FALSE(decision.checkpoint);
  EXPECT_NE(decision.reason.find(path + ":"), std::string::npos) << decision.reason;
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
