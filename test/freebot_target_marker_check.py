#!/usr/bin/env python3
"""rostest of freebot_target_marker.py (test/freebot_target_marker.test): its interactive marker
server spoken to as rviz speaks to it, on the real topics of Debian's interactive_markers
(<server>/update_full, <server>/update, <server>/feedback):
  1. the marker 'target' is offered in link0 (the chain's base) at ~initial (Table II's target A);
  2. a drag (POSE_UPDATE feedback) sends no goal; the release (MOUSE_UP) sends exactly the
     released pose as a goal in link0 (the chain's base, the marker's default ~frame) of the
     move_freebot action (recorded on its goal topic; no action server runs here);
  3. a goal from elsewhere (ik_target) moves the marker; a position-only one (zero quaternion)
     keeps the marker's orientation.
~position_only (false): the node runs with ~position_only, so the goal's quaternion is all zero.
"""
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Pose, PoseStamped
from visualization_msgs.msg import InteractiveMarkerFeedback, InteractiveMarkerInit, \
    InteractiveMarkerUpdate

from spherical_robots.msg import MoveFreebotActionGoal

from spherical_robots_testing import Recorder, wait_until

PKG = 'spherical_robots'
NAME = 'freebot_target_marker_check'
TABLE_II_A = [0.0036, 0.1636, 0.0924, 0.8610, 0.4687, 0.1356, 0.1437]  # x y z, qw qx qy qz
DEADLINE = 30.0  # [s] wall


def pose_list(pose):
    p, o = pose.position, pose.orientation
    return [p.x, p.y, p.z, o.w, o.x, o.y, o.z]


class FreebotTargetMarkerCheck(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        server = rospy.get_param('~server', 'freebot_target')
        cls.inits = Recorder(server + '/update_full', InteractiveMarkerInit)
        cls.updates = Recorder(server + '/update', InteractiveMarkerUpdate)
        cls.goals = Recorder('move_freebot/goal', MoveFreebotActionGoal)
        cls.feedback = rospy.Publisher(server + '/feedback', InteractiveMarkerFeedback,
                                       queue_size=10)
        cls.ik_target = rospy.Publisher('ik_target', PoseStamped, queue_size=10)

    def marker_poses(self):
        """The poses of 'target' in the update messages so far, in order."""
        poses = []
        for msg in self.updates.since(0):
            poses += [p.pose for p in msg.poses if p.name == 'target']
            poses += [m.pose for m in msg.markers if m.name == 'target']
        return poses

    def send_feedback(self, event, pose):
        feedback = InteractiveMarkerFeedback(client_id='/rviz/InteractiveMarkers',
                                             marker_name='target', event_type=event, pose=pose)
        feedback.header.frame_id = 'link0'
        feedback.header.stamp = rospy.Time.now()
        self.feedback.publish(feedback)

    def marker_after(self, goal, what):
        """The marker's pose once the server has moved it to `goal` (sent on ik_target)."""
        x = goal.pose.position.x
        self.ik_target.publish(goal)
        wait_until(lambda: any(abs(p.position.x - x) < 1e-9 for p in self.marker_poses()),
                   'the marker at ' + what, DEADLINE)
        return [p for p in self.marker_poses() if abs(p.position.x - x) < 1e-9][-1]

    def test_01_offers_the_target_at_table_ii_a(self):
        wait_until(lambda: self.inits.count() > 0, 'update_full', DEADLINE)
        markers = {m.name: m for m in self.inits.last().markers}
        self.assertIn('target', markers)
        target = markers['target']
        self.assertEqual(target.header.frame_id, 'link0')
        for got, want in zip(pose_list(target.pose), TABLE_II_A):
            self.assertAlmostEqual(got, want, places=9)
        self.assertGreaterEqual(len(target.controls), 7)  # the body and six rings/arrows

    def test_02_release_sends_the_pose_as_a_goal(self):
        wait_until(lambda: self.feedback.get_num_connections() > 0, 'the server on feedback',
                   DEADLINE)
        # interactive_markers' server ignores a new client's feedback for 1 s after the marker's
        # insertion (its guard against two clients dragging at once); a person is slower.
        wait_until(lambda: self.inits.count() > 0, 'update_full', DEADLINE)
        time.sleep(1.5)
        dragged = Pose()
        dragged.position.x, dragged.position.y, dragged.position.z = 0.05, 0.12, 0.15
        dragged.orientation.w = 1.0
        self.send_feedback(InteractiveMarkerFeedback.POSE_UPDATE, dragged)
        time.sleep(0.5)
        self.assertEqual(self.goals.since(0), [], 'a goal while dragging')
        # The release follows the drag on the same connection, so the server handled the drag
        # before it: one goal, the released pose, proves the drag sent none.
        released = Pose()
        released.position.x, released.position.y, released.position.z = 0.06, 0.11, 0.14
        released.orientation.w, released.orientation.z = 0.8, 0.6
        self.send_feedback(InteractiveMarkerFeedback.MOUSE_UP, released)
        wait_until(lambda: self.goals.count() > 0, 'a goal on release', DEADLINE)
        time.sleep(0.5)
        goals = self.goals.since(0)
        self.assertEqual(len(goals), 1)
        goal = goals[0].goal.target
        self.assertEqual(goal.header.frame_id, 'link0')
        expected = pose_list(released)
        if rospy.get_param('~position_only', False):
            expected[3:] = [0.0, 0.0, 0.0, 0.0]  # freebot_ik's position-only goal
        self.assertEqual(pose_list(goal.pose), expected)

    def test_03_goals_from_elsewhere_move_the_marker(self):
        wait_until(lambda: self.ik_target.get_num_connections() > 0,
                   'the marker node on ik_target', DEADLINE)
        full = PoseStamped()
        full.header.frame_id = 'link0'
        full.pose.position.x, full.pose.position.y, full.pose.position.z = 0.1151, 0.1489, 0.0291
        full.pose.orientation.w, full.pose.orientation.x = 0.6, 0.8
        self.assertEqual(pose_list(self.marker_after(full, 'the full-pose goal')),
                         pose_list(full.pose))
        position_only = PoseStamped()
        position_only.header.frame_id = 'link0'
        position_only.pose.position.x, position_only.pose.position.z = 0.2, 0.05
        kept = self.marker_after(position_only, 'the position-only goal')
        self.assertEqual(pose_list(kept)[:3], [0.2, 0.0, 0.05])
        self.assertEqual(pose_list(kept)[3:], [0.6, 0.8, 0.0, 0.0])  # the marker's, kept


if __name__ == '__main__':
    rospy.init_node(NAME)
    rostest.rosrun(PKG, NAME, FreebotTargetMarkerCheck)
