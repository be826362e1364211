#!/usr/bin/env python3
"""rostest of launch/rotor_stack.launch (test/rotor_stack*.test), in the stack's namespace.

Calls rotor_planner/plan for ~k, ~steps, ~target (u [m], v [m], psi [rad]), executes the shortest
plan (rotor_planner/execute) and waits for execution_done; then the plant's odometry must be at
the target: centre within ~position_bound [m] of (u, v, R) and the attitude within
~attitude_bound [rad] of R_z(-psi) (back at the south pole, eq 2 with u_o = v_o = 0). Also: the
set-points stream on actuators/command as rotor_1, rotor_2 within ~max_velocity and end at zero,
driven_path ends where odom does, joint_states name both rotors, tf world -> <prefix>base_link.
Prints the end error (docs/results.md quotes it).
"""
import functools
import math
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
        wall, sim = time.time() - wall_start, rospy.Time.now().to_sec() - sim_start
        self.assertEqual(self.done.last().data, 0)

        pose = self.odom.last().pose.pose
        error = math.hypot(pose.position.x - u, pose.position.y - v)
        attitude = (pose.orientation.w, pose.orientation.x, pose.orientation.y, pose.orientation.z)
        expected = (math.cos(0.5 * psi), 0.0, 0.0, -math.sin(0.5 * psi))  # R_z(-psi)
        angle = quaternion_angle(attitude, expected)
        print('rotor stack end error: position %.3e m (%.3e R), attitude %.3e rad; '
              'execution %.2f s simulated, %.2f s wall; plan a %.5f m, b %.5f m, gamma %.5f'
              % (error, error / RADIUS, angle, sim, wall, plan.a[0], plan.b[0], plan.gamma[0]))
        self.assertLessEqual(error, self.position_bound)
        self.assertLessEqual(angle, self.attitude_bound)
        self.assertAlmostEqual(pose.position.z, RADIUS, delta=1e-9)

        commands = self.commands.since(0)
        self.assertGreater(len(commands), 100)
        for msg in commands:
            self.assertEqual(list(msg.name), ['rotor_1', 'rotor_2'])
            self.assertLessEqual(max(abs(x) for x in msg.velocity), self.max_velocity)
        self.assertLessEqual(max(abs(x) for x in commands[-1].velocity), 1e-9)
        self.assertGreater(max(abs(x) for msg in commands for x in msg.velocity), 1.0)

        driven = self.driven.last()
        self.assertIsNotNone(driven)
        self.assertEqual(driven.header.frame_id, 'world')
        self.assertGreater(len(driven.poses), 50)
        end = driven.poses[-1].pose.position
        self.assertLess(math.hypot(end.x - pose.position.x, end.y - pose.position.y), 1e-3)

    def test_02_joint_states_and_tf(self):
        wait_until(lambda: self.joints.last() is not None, 'joint_states')
        self.assertEqual(list(self.joints.last().name), ['rotor_1', 'rotor_2'])
        transform = self.tf_buffer.lookup_transform('world', self.prefix + 'base_link',
                                                    rospy.Time(0), rospy.Duration(10.0))
        self.assertAlmostEqual(transform.transform.translation.z, RADIUS, delta=1e-9)
        self.tf_buffer.lookup_transform(self.prefix + 'base_link', self.prefix + 'rotor_1_pair',
                                        rospy.Time(0), rospy.Duration(10.0))


if __name__ == '__main__':
    rostest.rosrun(PKG, 'rotor_stack_check', RotorStackCheck)
