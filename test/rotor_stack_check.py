#!/usr/bin/env python3
"""rostest of launch/rotor_stack.launch (test/rotor_stack*.test), in the stack's namespace.

Calls rotor_planner/plan for ~k, ~steps, ~target (u [m], v [m], psi [rad]), executes the shortest
plan (rotor_planner/execute) and waits for execution_done; then the plant's odometry must be at
the target: centre within ~position_bound [m] of (u, v, R) and the attitude within
~attitude_bound [rad] of R_z(-psi) (back at the south pole, eq 2 with u_o = v_o = 0). Also: the
set-points stream on actuators/command as rotor_1, rotor_2 within ~max_velocity and end at zero,
driven_path ends where odom does, joint_states name both rotors, tf map -> <prefix>odom ->
<prefix>base_link (the shell itself).
With ~start_up true the stack plans and executes the manoeuvre itself (rotor_stack.launch
execute:=true) and this check only waits for its end. With ~batch true (a stack in lock-step) the
rest must also equal where `sphere_sim rotor-execute` comes to rest on the same scenario
(docs/lockstep.md, "Equal to the batch run"), centre and attitude to 1e-9: the bound is the batch
run's figure itself. The scenario's other launch arguments are given as ~actuator_models,
~actuator_time_constant, ~corrections, ~correction_tolerance, ~correction_tilt_tolerance. Rotors
with noise equal the batch run only from a start-up manoeuvre: the noise drawn before a request
from outside depends on when it arrives.
Prints the end error (docs/results.md quotes it).
"""
import csv
import functools
import math
import os
import subprocess
import time
import unittest

import rospy
import rostest
import tf2_ros
from nav_msgs.msg import Odometry, Path
from sensor_msgs.msg import JointState
from std_msgs.msg import UInt32

from spherical_robots.srv import PlanRotorMotion, PlanRotorMotionRequest
import spherical_robots_testing as testing
from spherical_robots_testing import Recorder, quaternion_angle

PKG = 'spherical_robots'
WALL_DEADLINE = 150.0  # [s] wall, for the whole execution (about 14 s simulated)
RADIUS = 0.1           # [m], launch/rotor_stack.launch


# Every wait of this script is bounded by WALL_DEADLINE.
wait_until = functools.partial(testing.wait_until, timeout=WALL_DEADLINE)


# The launch arguments of the scenario that sphere_sim rotor-execute takes too, as ~parameters.
BATCH_OPTIONS = (('actuator_models', '--actuator-models'),
                 ('actuator_time_constant', '--actuator-time-constant'),
                 ('corrections', '--corrections'), ('correction_tolerance', '--correction-tolerance'),
                 ('correction_tilt_tolerance', '--correction-tilt-tolerance'))


def batch_pose(k, steps, target, at=None):
    """Where `sphere_sim rotor-execute` has the sphere on this scenario `at` [s] after its first
    step (None: the end of its default duration, at rest): (centre (x, y) [m], attitude (w, x, y,
    z), the row's t)."""
    import roslib.packages
    import rospkg
    out = '/tmp/rotor_stack_check_batch_%d.csv' % os.getpid()
    command = [roslib.packages.find_node(PKG, 'sphere_sim')[0], 'rotor-execute',
               '--k', repr(k), '--steps', str(steps), '--target', ','.join(map(repr, target)),
               '--log-rate', '50', '--config', rospkg.RosPack().get_path(PKG), '--out', out]
    if at is not None:
        command += ['--duration', repr(at)]
    for name, option in BATCH_OPTIONS:
        if rospy.has_param('~' + name):
            command += [option, str(rospy.get_param('~' + name))]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    with open(out) as f:
        last = list(csv.DictReader(f))[-1]
    os.remove(out)
    return ((float(last['x']), float(last['y'])),
            tuple(float(last[q]) for q in ('qw', 'qx', 'qy', 'qz')), float(last['t']))


class RotorStackCheck(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('rotor_stack_check')
        cls.prefix = rospy.get_param('~frame_prefix', 'rotor/')
        cls.k = rospy.get_param('~k', 2.5)
        cls.steps = rospy.get_param('~steps', 2)
        cls.target = [float(x) for x in str(rospy.get_param('~target', '0.05,0.03,0.4')).split(',')]
        cls.position_bound = float(rospy.get_param('~position_bound'))
        cls.attitude_bound = float(rospy.get_param('~attitude_bound'))
        cls.max_velocity = rospy.get_param('~max_velocity', 25.0)
        cls.odom = Recorder('odom', Odometry)
        cls.joints = Recorder('joint_states', JointState)
        cls.commands = Recorder('actuators/command', JointState)
        cls.driven = Recorder('driven_path', Path)
        cls.done = Recorder('execution_done', UInt32)
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)

    def test_01_plan_execute_reach_target(self):
        u, v, psi = self.target
        wall_start, sim_start = time.time(), rospy.Time.now().to_sec()
        if not rospy.get_param('~start_up', False):
            rospy.wait_for_service('rotor_planner/plan', timeout=60.0)
            plan = rospy.ServiceProxy('rotor_planner/plan', PlanRotorMotion)(PlanRotorMotionRequest(
                k=self.k, steps=self.steps, u_a=u, v_a=v, psi=psi, max_radius=0.0, heading_turns=0))
            self.assertTrue(plan.success, plan.reason)
            self.assertLessEqual(plan.final_error[0], 1e-6)
            wait_until(lambda: self.odom.last() is not None, 'odom')
            publisher = rospy.Publisher('rotor_planner/execute', UInt32, queue_size=1, latch=True)
            wait_until(lambda: publisher.get_num_connections() > 0, 'rotor_planner/execute subscriber')
            wall_start, sim_start = time.time(), rospy.Time.now().to_sec()
            publisher.publish(UInt32(0))
        wait_until(lambda: self.done.last() is not None, 'execution_done')
        done_at = rospy.Time.now()
        wall, sim = time.time() - wall_start, done_at.to_sec() - sim_start
        self.assertEqual(self.done.last().data, 0)
        # odom comes on a connection of its own: wait for one from the end on.
        wait_until(lambda: self.odom.last().header.stamp >= done_at, 'odom after execution_done')
        end = self.odom.last()

        pose = end.pose.pose
        error = math.hypot(pose.position.x - u, pose.position.y - v)
        attitude = (pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z)
        expected = (math.cos(0.5 * psi), 0.0, 0.0, -math.sin(0.5 * psi))  # R_z(-psi)
        angle = quaternion_angle(attitude, expected)
        print('rotor stack end error: position %.3e m (%.3e R), attitude %.3e rad; '
              'execution %.2f s simulated, %.2f s wall' % (error, error / RADIUS, angle, sim, wall))
        self.assertLessEqual(error, self.position_bound)
        self.assertLessEqual(angle, self.attitude_bound)
        self.assertAlmostEqual(pose.position.z, RADIUS, delta=1e-9)
        if rospy.get_param('~batch', False):
            # From a start-up manoeuvre the batch run's clock is the stack's from its first step
            # (the first odom: time starts once this check is subscribed); with noisy rotors the
            # sphere drifts at rest, so the poses are compared at the same time.
            at = None
            if rospy.get_param('~start_up', False):
                at = (end.header.stamp - self.odom.since(0)[0].header.stamp).to_sec()
            centre, batch_attitude, t = batch_pose(self.k, self.steps, self.target, at)
            print('batch run at t = %.3f s: position %.17g, %.17g m; stack: %.17g, %.17g m'
                  % (t, centre[0], centre[1], pose.position.x, pose.position.y))
            if at is not None:
                self.assertAlmostEqual(t, at, delta=1e-9)
            self.assertLessEqual(abs(pose.position.x - centre[0]), 1e-9)
            self.assertLessEqual(abs(pose.position.y - centre[1]), 1e-9)
            # Component by component: an angle from acos is not resolved below ~1e-8 rad.
            for stack_q, batch_q in zip(attitude, batch_attitude):
                self.assertLessEqual(abs(stack_q - batch_q), 1e-9)

        commands = self.commands.since(0)
        self.assertGreater(len(commands), 100)
        for msg in commands:
            self.assertEqual(list(msg.name), ['rotor_1', 'rotor_2'])
            self.assertLessEqual(max(abs(x) for x in msg.velocity), self.max_velocity)
        self.assertLessEqual(max(abs(x) for x in commands[-1].velocity), 1e-9)
        self.assertGreater(max(abs(x) for msg in commands for x in msg.velocity), 1.0)

        driven = self.driven.last()
        self.assertIsNotNone(driven)
        self.assertEqual(driven.header.frame_id, self.prefix + 'odom')
        self.assertGreater(len(driven.poses), 50)
        end = driven.poses[-1].pose.position
        self.assertLess(math.hypot(end.x - pose.position.x, end.y - pose.position.y), 1e-3)

    def test_02_joint_states_and_tf(self):
        wait_until(lambda: self.joints.last() is not None, 'joint_states')
        self.assertEqual(list(self.joints.last().name), ['rotor_1', 'rotor_2'])
        transform = self.tf_buffer.lookup_transform('map', self.prefix + 'base_link',
                                                    rospy.Time(0), rospy.Duration(10.0))
        self.assertAlmostEqual(transform.transform.translation.z, RADIUS, delta=1e-9)
        odom = self.odom.last()
        self.assertEqual(odom.header.frame_id, self.prefix + 'odom')
        self.assertEqual(odom.child_frame_id, self.prefix + 'base_link')
        self.assertTrue(all(v > 0.0 for v in odom.pose.covariance[::7]))
        self.tf_buffer.lookup_transform(self.prefix + 'base_link', self.prefix + 'rotor_1_pair',
                                        rospy.Time(0), rospy.Duration(10.0))


if __name__ == '__main__':
    rostest.rosrun(PKG, 'rotor_stack_check', RotorStackCheck)
