#!/usr/bin/env python3
"""The FreeBOT stack's goal sequence when freebot_ik dies mid-goal (rostest,
test/freebot_ik_respawn.test; docs/conventions.md, "When a node dies").

freebot_ik is killed (SIGKILL) while it drives the chain to the sequence's first target, and
roslaunch restarts it (respawn:=true). The goal died with the old process: the sequence must send
that target again to the new one, and every target must then be reached, each result ARRIVED
within the action's tolerances (private ~position_bound [m], ~orientation_bound [rad]), within
~timeout [s] of wall time. Before the goal sequence watched its server, it waited for the lost
goal's result until the stack's end.
"""
import os
import signal
import threading
import unittest

import rospy
import rostest

from spherical_robots.msg import MoveFreebotActionGoal, MoveFreebotActionResult, MoveFreebotResult
from spherical_robots_testing import pid_of, wait_until


class FreebotIkRespawn(unittest.TestCase):

    def test_the_sequence_reaches_every_target_after_freebot_ik_restarts(self):
        rospy.init_node('freebot_ik_respawn_check')
        last_target = rospy.get_param('goal_sequence/targets')[-1][:3]
        position_bound = float(rospy.get_param('~position_bound'))
        orientation_bound = float(rospy.get_param('~orientation_bound'))
        timeout = float(rospy.get_param('~timeout'))
        lock = threading.Lock()
        goals, results = [], {}  # (id, target position) in order; id -> result

        def on_goal(msg):
            p = msg.goal.target.pose.position
            with lock:
                goals.append((msg.goal_id.id, [p.x, p.y, p.z]))

        def on_result(msg):
            with lock:
                results[msg.status.goal_id.id] = msg.result

        rospy.Subscriber('move_freebot/goal', MoveFreebotActionGoal, on_goal, queue_size=10)
        rospy.Subscriber('move_freebot/result', MoveFreebotActionResult, on_result, queue_size=10)
        wait_until(lambda: goals, 'a goal', 60.0)
        pid = pid_of(rospy.resolve_name('freebot_ik'))
        self.assertIsNotNone(pid, 'no process for freebot_ik')
        with lock:
            killed, target = goals[-1]
            self.assertNotIn(killed, results, 'the goal ended before the kill')
        os.kill(pid, signal.SIGKILL)
        rospy.loginfo('killed freebot_ik (pid %d) while it drove to %s', pid, target)

        def last_target_reached():
            with lock:
                return any(t == last_target and i in results for i, t in goals)
        wait_until(last_target_reached, 'a result for the last target %s' % last_target, timeout)
        restarted = pid_of(rospy.resolve_name('freebot_ik'))
        self.assertNotIn(restarted, (None, pid), 'freebot_ik was not restarted')
        with lock:
            self.assertNotIn(killed, results, 'the killed freebot_ik\'s goal had a result')
            after = goals[[i for i, _ in goals].index(killed) + 1:]
            self.assertTrue(after and after[0][1] == target,
                            'the next goal after the kill was %s, not the lost target %s again'
                            % (after[:1], target))
            for goal_id, _ in after:
                verdict = results[goal_id]
                rospy.loginfo('%s: %s', goal_id, verdict.message)
                self.assertEqual(verdict.status, MoveFreebotResult.ARRIVED, verdict.message)
                self.assertLessEqual(verdict.position_error, position_bound, verdict.message)
                self.assertLessEqual(verdict.orientation_error, orientation_bound, verdict.message)

if __name__ == '__main__':
    rostest.rosrun('spherical_robots', 'freebot_ik_respawn', FreebotIkRespawn)
