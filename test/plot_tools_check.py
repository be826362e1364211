#!/usr/bin/env python3
"""Test of the bag plotting tools (test/plot_tools.test): plot_terrain_run.py, plot_norma_run.py,
plot_rotor_run.py and plot_freebot_run.py run as a user runs them, on bags this test writes with
known motions, so what they print is checked against closed forms:
  * terrain: a 3R run whose turn set-point flips sign on every command after 40 s and whose
    lateral one flips below 0.01 rad/s: the summary counts the flips of the first only;
  * Norma: the state moves along X = 0.1 t, Y = 0.2 t at 1 kHz for 2 s, the desired point runs
    0.01 m ahead in X: the plot is written and spans t = 0.01-2.00 s;
  * rotor: the plan ends at (0.05, 0.03) m with the attitude turned 0.4 rad about z; the centre
    ends 3 mm, 4 mm off (5 mm: a 3-4-5 triangle) turned 0.41 rad: 0.005 m and 0.01 rad printed;
  * FreeBOT: the end-effector approaches a goal at a known rate; its errors to the goal in force
    (goal_errors) are the closed-form distances and angles, a goal given with a quaternion of
    norm 2 included, and the verdicts are printed;
  * a bag without the tool's topics, and a file that is no bag, end with exit status 1 and a
    one-line message naming the file and what is missing; a wrong quaternion (0, 0, 0, 0) goal
    asks for a position only (no orientation error).
The tools are found beside this script (the package's installed scripts).
"""
import math
import os
import subprocess
import sys
import tempfile
import unittest

import rosbag
import rospy
import rostest
from geometry_msgs.msg import Point, Pose, PoseStamped, Quaternion
from nav_msgs.msg import Odometry, Path
from sensor_msgs.msg import JointState
from spherical_robots.msg import (FreebotState, MoveFreebotActionResult, MoveFreebotResult,
                                  NormaState, TerrainState, TrackingError)

# The plotting tools are user programs in scripts/, beside this test's directory.
SCRIPTS = os.path.join(os.path.dirname(os.path.realpath(__file__)), '..', 'scripts')
sys.path.insert(0, SCRIPTS)
import plot_freebot_run  # noqa: E402
import plot_norma_run  # noqa: E402


def stamp(t):
    return rospy.Time.from_sec(t)


def yaw(angle):
    return Quaternion(0.0, 0.0, math.sin(angle / 2.0), math.cos(angle / 2.0))


def run_tool(tool, *args):
    result = subprocess.run([sys.executable, os.path.join(SCRIPTS, tool)] + list(args),
                            capture_output=True, text=True, timeout=120)
    return result.returncode, result.stdout, result.stderr


class PlotToolsCheck(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix='plot_tools_check.')

    def path(self, name):
        return os.path.join(self.dir, name)

    def assertPng(self, path):
        with open(path, 'rb') as f:
            self.assertEqual(f.read(8), b'\x89PNG\r\n\x1a\n', '%s is not a PNG' % path)

    def test_terrain_sign_changes(self):
        # 50 Hz for 60 s: theta 0.5 rad/s throughout; psi +-0.3 alternating on every command (it
        # flips on each of the 1001 steps from t = 40 s, and before, uncounted); phi alternates
        # +-0.005, below the 0.01 rad/s floor.
        bag_path = self.path('terrain.bag')
        with rosbag.Bag(bag_path, 'w') as bag:
            for k in range(1, 3001):
                t = k * 0.02
                state = TerrainState(robot_type='3R', contact_model='paper',
                                     contact_point=Point(0.1 * t, 0.0, 0.0))
                state.header.stamp = stamp(t)
                bag.write('/sphere/terrain_state', state, stamp(t))
                error = TrackingError(desired=Point(0.1 * t, 0.0, 0.0), error_norm=0.001)
                error.header.stamp = stamp(t)
                bag.write('/sphere/tracking_error', error, stamp(t))
                sign = 1.0 if k % 2 else -1.0
                command = JointState(name=['theta', 'phi', 'psi'],
                                     velocity=[0.5, 0.005 * sign, 0.3 * sign])
                command.header.stamp = stamp(t)
                bag.write('/sphere/actuators/command', command, stamp(t))
        code, out, err = run_tool('plot_terrain_run.py', bag_path, '--out', self.path('terrain.png'))
        self.assertEqual(code, 0, err)
        # Pairs from t = 40.00 s (the 2000th command) on: 1001 per joint, 3 joints.
        self.assertIn('sign changes:          1001 of 3003 steps of the commanded set-points '
                      'for t >= 40 s (phi, psi, theta)', out)
        self.assertPng(self.path('terrain.png'))

    def test_norma_bag(self):
        bag_path = self.path('norma.bag')
        with rosbag.Bag(bag_path, 'w') as bag:
            for k in range(1, 2001):
                t = k * 1e-3
                state = NormaState(x=0.1 * t, y=0.2 * t, torque=0.5, force=-1.0)
                state.header.stamp = stamp(t)
                state.q = [0.0, 0.0, 0.01 * t, 0.001 * t]
                bag.write('/norma/norma_state', state, stamp(t))
                if k % 10 == 1:
                    error = TrackingError(desired=Point(0.1 * t + 0.01, 0.2 * t, 0.0),
                                          error_norm=0.01)
                    error.header.stamp = stamp(t)
                    bag.write('/norma/tracking_error', error, stamp(t))
        code, out, err = run_tool('plot_norma_run.py', bag_path, self.path('norma.png'))
        self.assertEqual(code, 0, err)
        self.assertIn('t 0.01-2.00 s', out)
        self.assertPng(self.path('norma.png'))
        # Every column the figures draw, against the motion written (the desired point and |e|
        # the latest before each state: published every 10 ms, states read every 10th ms).
        # Stamps carry whole nanoseconds: t is known to 1e-9 s.
        col = plot_norma_run.read_bag(bag_path, '/norma')
        self.assertEqual(len(col['t']), 200)
        for i, t in enumerate(col['t']):
            self.assertAlmostEqual(col['X'][i], 0.1 * t, delta=1e-9)
            self.assertAlmostEqual(col['Y'][i], 0.2 * t, delta=1e-9)
            self.assertAlmostEqual(col['phi'][i], 0.01 * t, delta=1e-9)
            self.assertAlmostEqual(col['delta'][i], 0.001 * t, delta=1e-9)
            self.assertEqual((col['T'][i], col['F'][i], col['err'][i]), (0.5, -1.0, 0.01))
            # the latest tracking error, stamped t' at most 9 ms before the state: X_d = 0.1 t' + 0.01
            self.assertLessEqual(t - (col['Xd'][i] - 0.01) / 0.1, 0.009 + 1e-8)
            self.assertGreaterEqual(t - (col['Xd'][i] - 0.01) / 0.1, -1e-8)
            self.assertAlmostEqual(col['Yd'][i], 2.0 * (col['Xd'][i] - 0.01), delta=1e-12)

    def test_rotor_bag(self):
        bag_path = self.path('rotor.bag')
        with rosbag.Bag(bag_path, 'w') as bag:
            plan = Path()
            for s in (0.0, 0.5, 1.0):
                plan.poses.append(PoseStamped(pose=Pose(Point(0.05 * s, 0.03 * s, 0.1),
                                                        yaw(0.4 * s))))
            bag.write('/rotor/planned_path', plan, stamp(0.01))
            for k in range(1, 101):
                t, s = 0.1 * k, k / 100.0
                odom = Odometry()
                odom.header.stamp = stamp(t)
                odom.pose.pose = Pose(Point(0.053 * s, 0.034 * s, 0.1), yaw(0.41 * s))
                bag.write('/rotor/odom', odom, stamp(t))
                for topic in ('/rotor/actuators/command', '/rotor/actuators/state',
                              '/rotor/joint_states'):
                    joints = JointState(name=['rotor_1', 'rotor_2'], position=[s, -s],
                                        velocity=[1.0, -1.0])
                    joints.header.stamp = stamp(t)
                    bag.write(topic, joints, stamp(t))
        code, out, err = run_tool('plot_rotor_run.py', bag_path, self.path('rotor.png'))
        self.assertEqual(code, 0, err)
        words = out.split()
        distance = float(words[words.index('is') + 1])
        attitude = float(words[words.index('attitude') + 1])
        self.assertAlmostEqual(distance, 0.005, delta=1e-6, msg=out)
        self.assertAlmostEqual(attitude, 0.01, delta=1e-6, msg=out)
        self.assertPng(self.path('rotor.png'))

    def freebot_bag(self):
        """A 3-module chain's end-effector moving from (0, 0, 0.2) to a goal at (0.1, 0, 0.1)
        along a straight line in 1 s after the goal at t = 0.5 s, turned about z by 0.5 rad on
        the way (the goal's quaternion has norm 2), then a position-only goal."""
        bag_path = self.path('freebot.bag')
        goal_attitude = Quaternion(0.0, 0.0, 2.0 * math.sin(0.25), 2.0 * math.cos(0.25))
        with rosbag.Bag(bag_path, 'w') as bag:
            for k in range(0, 301):
                t = 0.01 * k
                s = min(max(t - 0.5, 0.0), 1.0)
                state = FreebotState(link=[yaw(0.1 * i * s) for i in (1, 2, 3)],
                                     base=[yaw(0.0)] * 3, heading=[0.0, 0.5 * s, -0.5 * s])
                state.header.stamp = stamp(t)
                state.end_effector = Pose(Point(0.1 * s, 0.0, 0.2 - 0.1 * s), yaw(0.5 * s))
                bag.write('/freebot/freebot_state', state, stamp(t))
            for t, goal in ((0.5, Pose(Point(0.1, 0.0, 0.1), goal_attitude)),
                            (2.0, Pose(Point(0.1, 0.0, 0.0), Quaternion(0.0, 0.0, 0.0, 0.0)))):
                message = PoseStamped(pose=goal)
                message.header.stamp = stamp(t)
                bag.write('/freebot/ik_target', message, stamp(t))
            result = MoveFreebotActionResult()
            result.header.stamp = stamp(1.5)
            result.result = MoveFreebotResult(status=MoveFreebotResult.ARRIVED, position_error=2e-5,
                                              orientation_error=3e-5, elapsed=1.0)
            bag.write('/freebot/move_freebot/result', result, stamp(1.5))
        return bag_path

    def test_freebot_errors_closed_form(self):
        run = plot_freebot_run.read_bag(self.freebot_bag(), '/freebot')
        errors = {round(t, 2): (p, o) for t, p, o in plot_freebot_run.goal_errors(run)}
        self.assertNotIn(0.49, errors, 'an error before the first goal')
        for t in (0.5, 1.0, 1.25, 1.5, 1.99):
            s = min(max(t - 0.5, 0.0), 1.0)
            position, orientation = errors[t]
            self.assertAlmostEqual(position, math.hypot(0.1 * (1.0 - s), 0.1 * (1.0 - s)),
                                   delta=1e-12, msg='t = %g' % t)
            self.assertAlmostEqual(orientation, 0.5 * (1.0 - s), delta=1e-9, msg='t = %g' % t)
        position, orientation = errors[2.5]
        self.assertAlmostEqual(position, 0.1, delta=1e-12)
        self.assertTrue(math.isnan(orientation), 'a position-only goal has no orientation error')

    def test_freebot_tool(self):
        code, out, err = run_tool('plot_freebot_run.py', self.freebot_bag(),
                                  self.path('freebot.png'))
        self.assertEqual(code, 0, err)
        self.assertIn('ARRIVED', out)
        self.assertIn('2.00e-05 m', out)
        self.assertPng(self.path('freebot.png'))

    def test_wrong_inputs(self):
        empty = self.path('empty.bag')
        with rosbag.Bag(empty, 'w') as bag:
            bag.write('/other', JointState(), stamp(1.0))
        not_a_bag = self.path('not_a.bag')
        with open(not_a_bag, 'w') as f:
            f.write('no bag\n')
        for tool in ('plot_norma_run.py', 'plot_rotor_run.py', 'plot_freebot_run.py'):
            missing = {'plot_norma_run.py': 'spherical_robots/NormaState',
                       'plot_rotor_run.py': 'nav_msgs/Odometry',
                       'plot_freebot_run.py': 'spherical_robots/FreebotState'}[tool]
            for path, expected in ((empty, missing), (not_a_bag, 'cannot read')):
                code, out, err = run_tool(tool, path, self.path('x.png'))
                self.assertEqual(code, 1, '%s %s: %s' % (tool, path, out + err))
                self.assertIn(path, err)
                self.assertIn(expected, err)
                self.assertEqual(len(err.strip().splitlines()), 1, err)


if __name__ == '__main__':
    rostest.rosrun('spherical_robots', 'plot_tools_check', PlotToolsCheck)
