#pragma once
// The lock-step clock mode of a plant (plant_clock.hpp, docs/lockstep.md): the plant steps,
// publishes /clock and its messages, then asks each participant of <ns>/lockstep/participants
// in turn (on the participant's own <participant>/lockstep/step) and waits for its
// acknowledgement (<ns>/lockstep/ack), then for the
// messages the participants published that the plant reads, and only then steps again. The
// decisions are core/lockstep_sequencer.hpp's; this class is their transport, pace and services.
// With a leader (a second stack on the master), the plant does not publish /clock: it is a
// participant of the leader's barrier, and each of its steps is asked for by the leader and
// acknowledged once its own participants have answered, so that every stack shares one barrier.

#include <ros/callback_queue_interface.h>
#include <ros/message_event.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/service_server.h>
#include <ros/subscriber.h>
#include <ros/wall_timer.h>
#include <std_srvs/Empty.h>
#include <std_srvs/Trigger.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "spherical_robots/LockstepAck.h"
#include "spherical_robots/core/clock_publication.hpp"
#include "spherical_robots/core/lockstep_inputs.hpp"
#include "spherical_robots/core/lockstep_pace.hpp"
#include "spherical_robots/core/lockstep_sequencer.hpp"
#include "spherical_robots/core/loop_cpu.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/plant_clock.hpp"

namespace spherical_robots {

class LockstepClock : public PlantClock {
 public:
  struct Settings {
    double step = 0.01;        ///< [s] > 0
    double speedup = 0.0;      ///< [-] cap on the pace; 0: as fast as the participants allow
    double timeout = 2.0;      ///< [s] of wall time before a silent participant is dropped
    double start_timeout = 10.0;  ///< [s] of wall time to wait for the participants to join
    double clock_rate = 1000.0;   ///< [Hz] of wall time: /clock messages at most; 0: every step
    /// Where the loop runs (core/loop_cpu.hpp); a follower's loop runs where its leader's does.
    LoopCpuSetting loop_cpu;
    std::vector<std::string> participants;   ///< resolved node names, in order of work
    std::vector<std::string> subscriptions;  ///< resolved topics the plant reads
    /// The namespace of the stack whose plant owns /clock; empty: this plant owns it.
    std::string leader;
    /// The plant's node name (its private namespace): its name in the leader's barrier.
    std::string name;
  };

  /// Advertises lockstep/step in nh's namespace, and, without a leader, /clock and the services
  /// lockstep/pause, lockstep/resume (std_srvs/Empty) and lockstep/step_once (std_srvs/Trigger).
  /// @throw std::invalid_argument on a bad setting, or if /use_sim_time is false.
  LockstepClock(ros::NodeHandle nh, Settings settings, Tick tick, Ready ready);

  ros::Time now() const override { return now_; }
  void resumeAt(const ros::Time& t) override { now_ = t; }
  double realTimeFactor() const override;
  void received(const std::string& topic, const ros::Time& stamp,
                const std::string& publisher) override;
  void report(diagnostic_updater::DiagnosticStatusWrapper& status) override;
  void finish() override;

 protected:
  const char* mode() const override { return "lockstep"; }

 private:
  void onAck(const ros::MessageEvent<spherical_robots::LockstepAck const>& event);
  void poll(const ros::WallTimerEvent&);
  /// At start: moves this process to the loop's CPU, chosen now if loop_cpu is auto.
  void placeLoop();
  /// Runs the next step now or when the pace allows, unless paused.
  void schedule();
  /// Steps to the next step time of its own, or to the leader's.
  void runStep();
  void runStepAt(const ros::Time& t);
  /// The step's last request was handed out: the next one, or the answer to the leader.
  void endStep();
  /// Hands out the step's requests until one must be waited for.
  void pump();
  /// Publishes /clock at the current step if it owns /clock and clock_publication_ says it is
  /// due (`waiting`: time stands still after this step for now).
  void publishClock(bool waiting);
  /// The publisher of `participant`'s requests, advertised on first use (a join is taken only
  /// once the participant has subscribed to it: a request sent before that would be lost).
  ros::Publisher& requestPublisher(const std::string& participant);
  /// Ends the step once the messages the plant waits for are in.
  void finishIfInputsIn();
  bool pause(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool resume(std_srvs::Empty::Request&, std_srvs::Empty::Response&);
  bool stepOnce(std_srvs::Trigger::Request&, std_srvs::Trigger::Response&);

  Settings settings_;
  Tick tick_;
  Ready ready_;
  LockstepSequencer sequencer_;
  LockstepInputs inputs_;
  LockstepPace pace_;
  ClockPublication clock_publication_;
  ros::CallbackQueueInterface* queue_;
  bool started_ = false;
  bool scheduled_ = false;
  bool in_run_step_ = false;  ///< inside runStepAt: a step that ends there is not called again from it
  bool awaiting_inputs_ = false;
  bool finished_ = false;
  int loop_cpu_ = -1;  ///< the CPU this loop runs on, named in every request; -1: none
  std::map<int, CpuTicks> cpu_ticks_at_creation_;  ///< for loop_cpu auto
  ros::Time now_;
  ros::WallTime created_wall_;
  ros::WallTime inputs_since_;
  unsigned long forged_ = 0;
  unsigned long unexpected_ = 0;
  std::vector<std::string> dropped_;  ///< dropped since the last report
  ros::Publisher clock_pub_;
  ros::NodeHandle nh_;
  std::map<std::string, ros::Publisher> request_pubs_;  ///< by participant: <participant>/lockstep/step
  ros::Subscriber ack_sub_;
  ros::ServiceServer pause_srv_, resume_srv_, step_srv_;
  ros::WallTimer poll_timer_;
  ros::WallTimer pace_timer_;
  ros::WallTimer finish_timer_;
  ros::NodeHandle leader_nh_;
  std::unique_ptr<LockstepParticipant> leader_link_;  ///< with a leader, once time has started
};

}  // namespace spherical_robots
