#!/usr/bin/env python3
"""rostest of rotor_planner (test/rotor_planner.test): the service against the paper's published
k = 2.5 solution (Svinin et al., section IV: h = R along +v_a with a1 = 0.300429 R,
gamma = 0.931883), the latched path and marker of the shortest plan, and the answers to a target
out of reach and to an invalid request. ~node names the node (relative)."""
import math
import threading
import time
import unittest

import rospy
import rostest
from nav_msgs.msg import Path
from visualization_msgs.msg import Marker
from spherical_robots.srv import PlanRotorMotion, PlanRotorMotionRequest

PKG = 'spherical_robots'
NAME = 'rotor_planner_check'


class RotorPlannerCheck(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        node = rospy.resolve_name(rospy.get_param('~node', 'rotor_planner'))
        cls.radius = float(rospy.get_param(node + '/sphere_radius'))
        rospy.wait_for_service(node + '/plan', timeout=30.0)
        cls.plan = rospy.ServiceProxy(node + '/plan', PlanRotorMotion)
        cls.lock = threading.Lock()
        cls.path = None
        cls.marker = None
        rospy.Subscriber('planned_path', Path, cls.onPath, queue_size=1)
        rospy.Subscriber('contact_curve', Marker, cls.onMarker, queue_size=1)

    @classmethod
    def onPath(cls, msg):
        with cls.lock:
            cls.path = msg

    @classmethod
    def onMarker(cls, msg):
        with cls.lock:
            cls.marker = msg

    def request(self, k, steps, u, v, psi):
        req = PlanRotorMotionRequest()
        req.k, req.steps, req.u_a, req.v_a, req.psi = k, steps, u, v, psi
        return self.plan(req)

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
        deadline = time.time() + 10.0
        while time.time() < deadline:
            with self.lock:
                if self.path is not None and self.marker is not None:
                    break
            time.sleep(0.05)
        with self.lock:
            path, marker = self.path, self.marker
        self.assertIsNotNone(path)
        self.assertIsNotNone(marker)
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


if __name__ == '__main__':
    rospy.init_node(NAME)
    rostest.rosrun(PKG, NAME, RotorPlannerCheck)
