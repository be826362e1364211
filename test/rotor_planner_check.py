#!/usr/bin/env python3
"""rostest of rotor_planner (test/rotor_planner.test): the service against the paper's published
k = 2.5 solution (Svinin et al., section IV: h = R along +v_a with a1 = 0.300429 R,
gamma = 0.931883), the latched path and marker of the shortest plan, and the answers to a target
out of reach and to an invalid request, and what /diagnostics says of refused requests (a plan
request, a goal of the execute_manoeuvre action with a plan_index beyond the plans: rejected) and
of an odom that is not finite (ignored, counted, the node alive). ~node names the node
(relative)."""
import math
import threading
import time
import unittest

import rospy
import rostest
from actionlib_msgs.msg import GoalStatus
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from nav_msgs.msg import Odometry, Path
from visualization_msgs.msg import Marker
from spherical_robots.msg import (ExecuteRotorManoeuvreAction, ExecuteRotorManoeuvreGoal,
                                  ExecuteRotorManoeuvreResult)
from spherical_robots.srv import PlanRotorMotion, PlanRotorMotionRequest

from spherical_robots_testing import GoalClient, Recorder, wait_until

PKG = 'spherical_robots'
NAME = 'rotor_planner_check'


class RotorPlannerCheck(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        node = rospy.resolve_name(rospy.get_param('~node', 'rotor_planner'))
        cls.node = node
        cls.radius = float(rospy.get_param(node + '/sphere_radius'))
        rospy.wait_for_service(node + '/plan', timeout=30.0)
        cls.plan = rospy.ServiceProxy(node + '/plan', PlanRotorMotion)
        cls.lock = threading.Lock()
        cls.paths = Recorder('planned_path', Path)
        cls.markers = Recorder('contact_curve', Marker)
        cls.status = None
        rospy.Subscriber('/diagnostics', DiagnosticArray, cls.onDiagnostics, queue_size=10)

    @classmethod
    def onDiagnostics(cls, msg):
        for status in msg.status:
            if 'rotor planner' in status.name:
                with cls.lock:
                    cls.status = status

    def wait_for_status(self, condition, what):
        deadline = time.time() + 20.0
        while time.time() < deadline:
            with self.lock:
                status = self.status
            if status is not None and condition(status):
                return status
            time.sleep(0.05)
        self.fail('no rotor planner diagnostics with %s; last: %s' % (what, status))

    def request(self, k, steps, u, v, psi):
        req = PlanRotorMotionRequest()
        req.k, req.steps, req.u_a, req.v_a, req.psi = k, steps, u, v, psi
        return self.plan(req)

    def test_00_diagnostics_before_any_odom(self):
        # No odom is published in this test: the node reports anyway, once a second.
        status = self.wait_for_status(lambda s: 'no message yet' in s.message,
                                      'the missing odom reported')
        self.assertEqual(status.level, DiagnosticStatus.WARN)
        values = dict((v.key, v.value) for v in status.values)
        self.assertEqual(values[rospy.resolve_name('odom') + ' accepted'], '0')

    def test_published_solution_and_its_path(self):
        R = self.radius
        res = self.request(2.5, 1, 0.0, R, 0.0)
        self.assertTrue(res.success, res.reason)
        self.assertGreaterEqual(len(res.a), 4)
        self.assertAlmostEqual(res.a[0] / R, 0.300429, delta=5e-7)
        self.assertAlmostEqual(res.b[0] / R, 0.300429, delta=5e-7)
        self.assertAlmostEqual(res.gamma[0], 0.931883, delta=5e-7)
        self.assertEqual(list(res.length), sorted(res.length))
        self.assertLessEqual(max(res.final_error), 1e-6)
        wait_until(lambda: self.paths.count() > 0 and self.markers.count() > 0,
                   'the latched path and contact curve', 10.0)
        path, marker = self.paths.last(), self.markers.last()
        start, end = path.poses[0].pose, path.poses[-1].pose
        self.assertAlmostEqual(start.position.x, 0.0, delta=1e-12)
        self.assertAlmostEqual(end.position.x, 0.0, delta=1e-8 * R)
        self.assertAlmostEqual(end.position.y, R, delta=1e-8 * R)
        self.assertAlmostEqual(end.position.z, R, delta=1e-12)
        # a = b: no net turn, so the sphere ends in its starting orientation.
        self.assertAlmostEqual(abs(end.orientation.w), 1.0, delta=1e-8)
        # The contact curve lies on the sphere and starts at its south pole.
        for p in marker.points:
            self.assertAlmostEqual(math.sqrt(p.x ** 2 + p.y ** 2 + p.z ** 2), R, delta=1e-12)
        self.assertAlmostEqual(marker.points[0].z, -R, delta=1e-12)

    def test_out_of_reach_gives_a_reason(self):
        res = self.request(2.5, 1, 100.0 * self.radius, 0.0, 0.0)
        self.assertFalse(res.success)
        self.assertEqual(len(res.a), 0)
        self.assertIn('no plan', res.reason)

    def test_invalid_request_is_answered(self):
        res = self.request(-1.0, 1, 0.0, self.radius, 0.0)
        self.assertFalse(res.success)
        self.assertIn('inertia ratio k', res.reason)
        res = self.request(2.5, 0, 0.0, self.radius, 0.0)
        self.assertFalse(res.success)
        self.assertIn('steps', res.reason)


    def publish_until_rejected(self, odom, msg, reason):
        """Publishes msg on odom until diagnostics give `reason` as the last rejection."""
        key = rospy.resolve_name('odom')
        deadline = time.time() + 20.0
        values = {}
        while time.time() < deadline:
            msg.header.stamp = rospy.Time.now()  # a stamp near the clock: rejected for `reason`
            odom.publish(msg)
            with self.lock:
                values = dict((v.key, v.value) for v in self.status.values) if self.status else {}
            if reason in values.get(key + ' last rejection', ''):
                break
            time.sleep(0.1)
        self.assertIn(reason, values.get(key + ' last rejection', ''), values)
        self.assertGreater(int(values.get(key + ' rejected', '0')), 0, values)
        self.assertEqual(values.get(key + ' accepted'), '0', values)

    def test_refusals_and_bad_odom_on_diagnostics(self):
        res = self.request(2.5, 0, 0.0, self.radius, 0.0)
        self.assertFalse(res.success)
        status = self.wait_for_status(lambda s: s.level == DiagnosticStatus.WARN
                                      and 'steps' in s.message, 'the refused request')
        self.assertIn('steps', dict((v.key, v.value) for v in status.values)['last problem'])
        client = GoalClient(self.node + '/execute_manoeuvre', ExecuteRotorManoeuvreAction, 30.0)
        client.send(ExecuteRotorManoeuvreGoal(k=2.5, steps=1, u_a=0.0, v_a=self.radius,
                                              plan_index=99))
        state, result = client.result('the goal rejected')
        self.assertEqual(state, GoalStatus.REJECTED, result.message)
        self.assertEqual(result.status, ExecuteRotorManoeuvreResult.REJECTED)
        self.assertIn('plan_index 99 refused', result.message)
        self.wait_for_status(lambda s: 'plan_index 99 refused' in s.message, 'the refused goal')
        odom = rospy.Publisher('odom', Odometry, queue_size=10)
        unset = Odometry()  # an all-zero orientation: no attitude
        self.publish_until_rejected(odom, unset, 'has norm 0, expected a unit quaternion')
        bad = Odometry()
        bad.pose.pose.position.x = float('nan')
        bad.pose.pose.orientation.w = 1.0
        self.publish_until_rejected(odom, bad, 'must be finite with magnitude <= 1000, got nan')
        # Still serving.
        self.assertTrue(self.request(2.5, 1, 0.0, self.radius, 0.0).success)


if __name__ == '__main__':
    rospy.init_node(NAME)
    rostest.rosrun(PKG, NAME, RotorPlannerCheck)
