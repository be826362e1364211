#!/usr/bin/env python3
"""rostest: two stacks on one master share one lock-step barrier (docs/lockstep.md, "Several
stacks"). The leader stack owns /clock; the follower (owns_clock:=false,
clock_leader:=<leader ns>) is a participant of the leader's barrier and runs its own participants
inside each of its steps. Both run the same scenario, so in one barrier they must publish the
same states at the same stamps, value for value, with no step missing in either; on timers the
follower would see the leader's /clock at the times the machine lets it.

Then the leader's services (docs/lockstep.md, "Services"): paused, time stands still; step_once
moves it by exactly one step, for both stacks; resumed, it runs on.

Parameters (private): leader, follower (namespaces, e.g. /sphere and /sphere2); duration [s]
compared from the start (the stacks run on: a plant that ends shuts the launch down, this test
with it); period [s] (the state's publication period).
"""
import math
import time
import unittest

import rospy
import rostest
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty, Trigger

from spherical_robots.msg import TerrainState
from spherical_robots_testing import Recorder, wait_until

WALL_DEADLINE = 240.0  # [s] for the whole run at the slowest pace a loaded machine gives
QUIET = 1.0  # [s] of wall time a paused clock must stay still


class SharedBarrier(unittest.TestCase):
    def test_follower_steps_with_the_leader(self):
        leader_ns = rospy.get_param('~leader')
        follower_ns = rospy.get_param('~follower')
        duration = float(rospy.get_param('~duration'))
        period = float(rospy.get_param('~period'))
        leader = Recorder(leader_ns + '/terrain_state', TerrainState)
        follower = Recorder(follower_ns + '/terrain_state', TerrainState)
        last = duration - period / 2

        def reached_end(recorder):
            msg = recorder.last()
            return msg is not None and msg.header.stamp.to_sec() >= last

        wait_until(lambda: reached_end(leader) and reached_end(follower),
                   'both stacks past %g s' % duration, WALL_DEADLINE)
        end = int(round(last * 1e9))
        lead = {m.header.stamp.to_nsec(): m for m in leader.since(0) if m.header.stamp.to_nsec() <= end}
        follow = {m.header.stamp.to_nsec(): m for m in follower.since(0)
                  if m.header.stamp.to_nsec() <= end}
        # The recorder may connect after time started (on a loaded machine): from the first stamp
        # both hold, every state of both.
        first = max(min(lead), min(follow))
        lead = {t: m for t, m in lead.items() if t >= first}
        follow = {t: m for t, m in follow.items() if t >= first}
        self.assertEqual(sorted(lead), sorted(follow),
                         'the stacks published states at different stamps')
        stamps = sorted(lead)
        self.assertGreaterEqual(stamps[-1] - stamps[0], int(duration / 2 * 1e9),
                                'less than half the run recorded')
        gaps = [b - a for a, b in zip(stamps, stamps[1:])]
        self.assertEqual(max(gaps), int(round(period * 1e9)), 'a step without a state')
        differing, largest = 0, 0.0
        for stamp, a in lead.items():
            b = follow[stamp]
            a.header.seq = b.header.seq = 0
            a.header.frame_id = b.header.frame_id = ''  # each stack's own <ns>/odom
            if a != b:
                differing += 1
                largest = max(largest, math.hypot(a.contact_point.x - b.contact_point.x,
                                                  a.contact_point.y - b.contact_point.y))
        rospy.loginfo('shared barrier: %d states at common stamps, %d differ (contact points by up '
                      'to %.3g m)', len(lead), differing, largest)
        self.assertEqual(differing, 0, 'the follower is not the same run as the leader: %d states '
                         'differ, contact points by up to %.3g m' % (differing, largest))

    def test_services_pause_step_once_and_resume(self):
        leader_ns = rospy.get_param('~leader')
        period = float(rospy.get_param('~period'))
        clock = Recorder('/clock', Clock)
        wait_until(lambda: clock.last() is not None, 'a /clock message', WALL_DEADLINE)
        call = {}
        for name, kind in (('pause', Empty), ('resume', Empty), ('step_once', Trigger)):
            rospy.wait_for_service(leader_ns + '/lockstep/' + name, timeout=30.0)
            call[name] = rospy.ServiceProxy(leader_ns + '/lockstep/' + name, kind)
        refused = call['step_once']()
        self.assertFalse(refused.success, 'step_once while running: ' + refused.message)

        call['pause']()
        time.sleep(QUIET)  # a step in flight when the pause came ends
        paused_at = clock.last().clock
        time.sleep(QUIET)
        self.assertEqual(clock.last().clock, paused_at, 'time moved while paused')

        answer = call['step_once']()
        self.assertTrue(answer.success, answer.message)
        wait_until(lambda: clock.last().clock > paused_at, 'the single step', 30.0)
        time.sleep(QUIET)
        steps = [m.clock for m in clock.since(0) if m.clock > paused_at]
        self.assertEqual(len(steps), 1, 'step_once moved time by %d steps' % len(steps))

        call['resume']()
        wait_until(lambda: (clock.last().clock - steps[0]).to_sec() > 10 * period,
                   'time running again after resume', 60.0)

if __name__ == '__main__':
    rospy.init_node('shared_barrier_check')
    rostest.rosrun('spherical_robots', 'shared_barrier_check', SharedBarrier)
