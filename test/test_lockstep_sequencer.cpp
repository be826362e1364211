// The lock-step barrier's decisions (core/lockstep_sequencer.hpp, core/lockstep_inputs.hpp,
// docs/lockstep.md): order of work, what each participant is told to wait for, skipped steps,
// forged, repeated and out-of-order acknowledgements, drops after silence, rejoining.
#include <gtest/gtest.h>

#include <stdexcept>

#include "spherical_robots/core/latest_per_publisher.hpp"
#include "spherical_robots/core/lockstep_inputs.hpp"
#include "spherical_robots/core/lockstep_sequencer.hpp"

namespace spherical_robots {
namespace {

constexpr std::int64_t kStep = 10'000'000;  // [ns] 0.01 s
const std::string kPlant = "/sphere/terrain_plant";
const std::string kController = "/sphere/pure_pursuit_controller";
const std::string kHardware = "/sphere/hardware_interface";

LockstepSequencer terrainLoop() {
  LockstepSequencer sequencer(kPlant, {kController, kHardware}, 2.0);
  sequencer.join(kController);
  sequencer.join(kHardware);
  return sequencer;
}

bool lists(const StepRequest& request, const std::string& topic, std::int64_t stamp) {
  for (const PublishedTopic& input : request.inputs)
    if (input.topic == topic && input.stamp == stamp) return true;
  return false;
}

const std::string* publisherOf(const StepRequest& request, const std::string& topic) {
  for (const PublishedTopic& input : request.inputs)
    if (input.topic == topic) return &input.publisher;
  return nullptr;
}

TEST(LockstepSequencer, AsksEachParticipantInOrderWithWhatWasPublishedSinceItLastWorked) {
  LockstepSequencer sequencer = terrainLoop();
  ASSERT_TRUE(sequencer.allExpectedJoined());
  sequencer.beginStep(kStep, {"/sphere/terrain_state"}, 0.0);

  const auto controller = sequencer.nextRequest(0.0);
  ASSERT_TRUE(controller);
  EXPECT_EQ(controller->participant, kController);
  EXPECT_TRUE(lists(*controller, "/sphere/terrain_state", kStep));
  EXPECT_FALSE(sequencer.nextRequest(0.0)) << "one participant at a time";
  EXPECT_EQ(sequencer.acknowledge(kController, kController, kStep, {"/sphere/actuators/command"}, 0),
            AckOutcome::kAccepted);

  const auto hardware = sequencer.nextRequest(0.0);
  ASSERT_TRUE(hardware);
  EXPECT_EQ(hardware->participant, kHardware);
  EXPECT_TRUE(lists(*hardware, "/sphere/actuators/command", kStep));
  EXPECT_TRUE(lists(*hardware, "/sphere/terrain_state", kStep));
  EXPECT_EQ(sequencer.acknowledge(kHardware, kHardware, kStep, {"/sphere/actuators/state"}, 0),
            AckOutcome::kAccepted);

  // Each input names its publisher: the owner for its own topics, the acknowledging sender for a
  // participant's.
  ASSERT_TRUE(publisherOf(*hardware, "/sphere/terrain_state"));
  EXPECT_EQ(*publisherOf(*hardware, "/sphere/terrain_state"), kPlant);
  ASSERT_TRUE(publisherOf(*hardware, "/sphere/actuators/command"));
  EXPECT_EQ(*publisherOf(*hardware, "/sphere/actuators/command"), kController);

  const auto plant = sequencer.nextRequest(0.0);
  ASSERT_TRUE(plant);
  EXPECT_EQ(plant->participant, kPlant) << "the plant's own request ends the step";
  EXPECT_TRUE(lists(*plant, "/sphere/actuators/state", kStep));
  ASSERT_TRUE(publisherOf(*plant, "/sphere/actuators/state"));
  EXPECT_EQ(*publisherOf(*plant, "/sphere/actuators/state"), kHardware);
  EXPECT_FALSE(sequencer.nextRequest(0.0));
  sequencer.endStep();

  // Next step: the controller is told of the actuator state the hardware published after it.
  sequencer.beginStep(2 * kStep, {}, 0.0);
  const auto again = sequencer.nextRequest(0.0);
  ASSERT_TRUE(again);
  EXPECT_TRUE(lists(*again, "/sphere/actuators/state", kStep));
  EXPECT_FALSE(lists(*again, "/sphere/terrain_state", kStep)) << "already told of it";
  EXPECT_FALSE(lists(*again, "/sphere/actuators/command", kStep)) << "its own, nothing new";
}

TEST(LockstepSequencer, SkipsAParticipantUntilTheStepItAskedFor) {
  LockstepSequencer sequencer = terrainLoop();
  sequencer.beginStep(kStep, {}, 0.0);
  ASSERT_EQ(sequencer.nextRequest(0.0)->participant, kController);
  sequencer.acknowledge(kController, kController, kStep, {}, 3 * kStep);
  ASSERT_EQ(sequencer.nextRequest(0.0)->participant, kHardware);
  sequencer.acknowledge(kHardware, kHardware, kStep, {}, 0);
  ASSERT_EQ(sequencer.nextRequest(0.0)->participant, kPlant);
  sequencer.endStep();
  sequencer.beginStep(2 * kStep, {}, 0.0);
  EXPECT_EQ(sequencer.nextRequest(0.0)->participant, kHardware) << "the controller is not due";
  sequencer.acknowledge(kHardware, kHardware, 2 * kStep, {}, 0);
  sequencer.nextRequest(0.0);
  sequencer.endStep();
  sequencer.beginStep(3 * kStep, {}, 0.0);
  EXPECT_EQ(sequencer.nextRequest(0.0)->participant, kController) << "due again at 3 steps";
}

TEST(LockstepSequencer, ForgedRepeatedAndOutOfOrderAcknowledgementsDoNotMoveTheBarrier) {
  LockstepSequencer sequencer = terrainLoop();
  sequencer.beginStep(kStep, {}, 0.0);
  ASSERT_EQ(sequencer.nextRequest(0.0)->participant, kController);
  // A third node claims to be the controller.
  EXPECT_EQ(sequencer.acknowledge("/intruder", kController, kStep, {}, 0), AckOutcome::kForged);
  // The hardware answers before its turn; a stale and a future step.
  EXPECT_EQ(sequencer.acknowledge(kHardware, kHardware, kStep, {}, 0), AckOutcome::kUnexpected);
  EXPECT_EQ(sequencer.acknowledge(kController, kController, 0, {}, 0), AckOutcome::kUnexpected);
  EXPECT_EQ(sequencer.acknowledge(kController, kController, 5 * kStep, {}, 0),
            AckOutcome::kUnexpected);
  ASSERT_NE(sequencer.awaited(), nullptr);
  EXPECT_EQ(*sequencer.awaited(), kController) << "still waiting for the real one";
  EXPECT_EQ(sequencer.acknowledge(kController, kController, kStep, {}, 0), AckOutcome::kAccepted);
  EXPECT_EQ(sequencer.nextRequest(0.0)->participant, kHardware);
  // Repeated: the barrier has moved on to the hardware.
  EXPECT_EQ(sequencer.acknowledge(kController, kController, kStep, {}, 0), AckOutcome::kUnexpected);
  ASSERT_NE(sequencer.awaited(), nullptr);
  EXPECT_EQ(*sequencer.awaited(), kHardware);
}

TEST(LockstepSequencer, NodeletsInThePlantsManagerSpeakWithTheManagersCallerId) {
  const std::string manager = "/sphere/nodelet_manager";
  LockstepSequencer sequencer(manager, {kController, kHardware}, 2.0);
  EXPECT_TRUE(sequencer.sentBy(manager, kController));
  EXPECT_FALSE(sequencer.sentBy("/sphere/other_manager", kController));
  EXPECT_TRUE(sequencer.sentBy(kHardware, kHardware)) << "a participant in a process of its own";
  sequencer.join(kController);
  sequencer.join(kHardware);
  sequencer.beginStep(kStep, {}, 0.0);
  ASSERT_EQ(sequencer.nextRequest(0.0)->participant, kController);
  EXPECT_EQ(sequencer.acknowledge("/intruder", kController, kStep, {}, 0), AckOutcome::kForged);
  EXPECT_EQ(sequencer.acknowledge(manager, kController, kStep, {}, 0), AckOutcome::kAccepted);
  EXPECT_EQ(sequencer.nextRequest(0.0)->participant, kHardware);
}

TEST(LockstepSequencer, DropsASilentParticipantAfterTheTimeoutAndTakesItBackWhenItRejoins) {
  LockstepSequencer sequencer = terrainLoop();
  sequencer.beginStep(kStep, {}, 100.0);
  ASSERT_EQ(sequencer.nextRequest(100.0)->participant, kController);
  EXPECT_FALSE(sequencer.dropSilent(101.9));
  const auto dropped = sequencer.dropSilent(102.1);
  ASSERT_TRUE(dropped);
  EXPECT_EQ(*dropped, kController);
  EXPECT_FALSE(sequencer.allExpectedJoined());
  // Time goes on: the hardware is asked next, and without the controller on later steps.
  EXPECT_EQ(sequencer.nextRequest(102.1)->participant, kHardware);
  sequencer.acknowledge(kHardware, kHardware, kStep, {}, 0);
  sequencer.nextRequest(102.1);
  sequencer.endStep();
  sequencer.beginStep(2 * kStep, {}, 102.2);
  EXPECT_EQ(sequencer.nextRequest(102.2)->participant, kHardware);
  sequencer.acknowledge(kHardware, kHardware, 2 * kStep, {}, 0);
  sequencer.nextRequest(102.2);
  sequencer.endStep();
  // Its late answer does not count; its join does.
  EXPECT_EQ(sequencer.acknowledge(kController, kController, kStep, {}, 0), AckOutcome::kUnexpected);
  EXPECT_TRUE(sequencer.join(kController));
  EXPECT_FALSE(sequencer.join(kController)) << "a repeated join changes nothing";
  sequencer.beginStep(3 * kStep, {}, 103.0);
  EXPECT_EQ(sequencer.nextRequest(103.0)->participant, kController);
  EXPECT_EQ(sequencer.participants()[0].drops, 1u);
}

TEST(LockstepSequencer, RejectsABadTimeoutARepeatedNameAndAStepThatDoesNotAdvance) {
  EXPECT_THROW(LockstepSequencer(kPlant, {kController}, 0.0), std::invalid_argument);
  EXPECT_THROW(LockstepSequencer(kPlant, {kController, kController}, 1.0), std::invalid_argument);
  LockstepSequencer sequencer = terrainLoop();
  sequencer.beginStep(kStep, {}, 0.0);
  EXPECT_THROW(sequencer.beginStep(2 * kStep, {}, 0.0), std::logic_error) << "step in progress";
  while (sequencer.nextRequest(0.0)) {
    const std::string* awaited = sequencer.awaited();
    if (!awaited) break;
    sequencer.acknowledge(*awaited, *awaited, kStep, {}, 0);
  }
  sequencer.endStep();
  EXPECT_THROW(sequencer.beginStep(kStep, {}, 0.0), std::logic_error) << "same time again";
}

TEST(LockstepInputs, WaitsForListedSubscriptionsWhicheverArrivesFirst) {
  const std::string command = "/sphere/actuators/command";
  LockstepInputs inputs({command});
  // The data before the request.
  inputs.received(command, kStep, kController);
  inputs.expect({{command, kStep, kController}, {"/sphere/terrain_state", kStep, kPlant}});
  EXPECT_TRUE(inputs.satisfied()) << "terrain_state is not one of its subscriptions";
  // The request before the data.
  inputs.expect({{command, 2 * kStep, kController}});
  EXPECT_FALSE(inputs.satisfied());
  ASSERT_EQ(inputs.missing().size(), 1u);
  inputs.received(command, kStep, kController);  // an old one again: not enough
  EXPECT_FALSE(inputs.satisfied());
  inputs.received(command, 2 * kStep, kController);
  EXPECT_TRUE(inputs.satisfied());
}

// A stray node's message on an input counts for nothing: one stamped with the step's time does
// not stand in for the loop's (which the node would then work without), and one stamped 1,000 s
// ahead does not satisfy every wait until then. Its publisher's rejected messages still count
// (docs/lockstep.md), so a bad command from the controller does not stall the step.
TEST(LockstepInputs, CountsOnlyTheNamedPublishersMessages) {
  const std::string odom = "/sphere/odom";
  const std::string stray = "/hostile_input_check";
  LockstepInputs inputs({odom});
  inputs.received(odom, 1000 * kStep + 1000'000'000'000, stray);
  inputs.received(odom, 2 * kStep, stray);
  inputs.expect({{odom, 2 * kStep, kPlant}});
  EXPECT_FALSE(inputs.satisfied()) << "the stray node's messages stand in for the plant's";
  ASSERT_EQ(inputs.missing(), std::vector<std::string>{odom});
  inputs.received(odom, 2 * kStep, kPlant);
  EXPECT_TRUE(inputs.satisfied());
  inputs.expect({{odom, 3 * kStep, kPlant}});
  EXPECT_FALSE(inputs.satisfied()) << "the message from the future satisfied a later wait";
  inputs.received(odom, 3 * kStep, kPlant);
  EXPECT_TRUE(inputs.satisfied());
  // A request that names no publisher (from a plant older than the field) takes any.
  inputs.expect({{odom, 4 * kStep, ""}});
  EXPECT_TRUE(inputs.satisfied()) << "the stray message from the future counts where any does";
}

// A message-driven participant (the friction drive, the FreeBOT IK, the Norma controller) works on
// the message stamped with the step's time from the publisher its request names: a stray node's
// message stamped alike, arriving after the loop's, does not replace it; nor before it.
TEST(LatestPerPublisher, TheStepsInputIsTheNamedPublishersMessage) {
  const std::string command = "/roller/drive/command";
  const std::string stray = "/hostile_input_check";
  LockstepInputs inputs({command});
  LatestPerPublisher<std::string> latest;
  latest.keep(kController, kStep, "loop's");
  latest.keep(stray, kStep, "stray, after");
  inputs.expect({{command, kStep, kController}});
  const std::optional<std::string> publisher = inputs.expectedPublisher(command);
  ASSERT_TRUE(publisher.has_value());
  EXPECT_EQ(*publisher, kController);
  const std::string* input = latest.at(kStep, *publisher);
  ASSERT_NE(input, nullptr);
  EXPECT_EQ(*input, "loop's");
  // Stray first, then the loop's.
  latest.keep(stray, 2 * kStep, "stray, before");
  latest.keep(kController, 2 * kStep, "loop's 2");
  input = latest.at(2 * kStep, kController);
  ASSERT_NE(input, nullptr);
  EXPECT_EQ(*input, "loop's 2");
  // Only a stray message stamped with the step's time: nothing to work on.
  latest.keep(stray, 3 * kStep, "stray only");
  EXPECT_EQ(latest.at(3 * kStep, kController), nullptr);
  // A request that names no publisher takes the latest to arrive of those stamped alike.
  latest.keep(kController, 4 * kStep, "loop's 4");
  latest.keep(stray, 4 * kStep, "stray 4");
  input = latest.at(4 * kStep, "");
  ASSERT_NE(input, nullptr);
  EXPECT_EQ(*input, "stray 4");
  EXPECT_EQ(latest.at(5 * kStep, ""), nullptr);
  // A topic the request does not list was not published in the loop: no input on it.
  inputs.expect({{"/roller/terrain_state", kStep, kPlant}});
  EXPECT_FALSE(inputs.expectedPublisher(command).has_value());
  inputs.expect({{command, kStep, ""}});
  ASSERT_TRUE(inputs.expectedPublisher(command).has_value());
  EXPECT_EQ(*inputs.expectedPublisher(command), "");
}

}  // namespace
}  // namespace spherical_robots

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
