#!/usr/bin/env python3
"""rostest of launch/rotor_stack.launch (test/rotor_stack*.test), in the stack's namespace.

Calls rotor_planner/plan for ~k, ~steps, ~target (u [m], v [m], psi [rad]), then executes the
shortest plan through rotor_planner's execute_manoeuvre action, with actionlib's own client, and
waits for its result (succeeded, EXECUTED; its feedback on the way); then the plant's odometry
must be at the target: centre within ~position_bound [m] of (u, v, R) and the attitude within
~attitude_bound [rad] of R_z(-psi) (back at the south pole, eq 2 with u_o = v_o = 0), and the
result's distance is that of the odometry. Also: the set-points stream on actuators/command as
rotor_1, rotor_2 within ~max_velocity and end at zero, driven_path ends where odom does,
joint_states name both rotors, tf map -> <prefix>odom -> <prefix>base_link (the shell itself).
With ~actions true, after it: goals the planner rejects (an invalid request, no plan, a
plan_index beyond the plans) while another executes, which goes on; a goal preempted by a second
one (the rotors to rest, the second executed); a cancel (the rotors to rest, the sphere stays put).
With ~start_up true the stack plans and executes the manoeuvre itself (rotor_stack.launch
execute:=true) and this check only waits for its end (on /diagnostics: the planner idle after one
execution). With ~batch true (a stack in lock-step) the
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
from actionlib_msgs.msg import GoalStatus
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from nav_msgs.msg import Odometry, Path
from sensor_msgs.msg import JointState

from spherical_robots.msg import (ExecuteRotorManoeuvreAction, ExecuteRotorManoeuvreGoal,
                                  ExecuteRotorManoeuvreResult)
from spherical_robots.srv import PlanRotorMotion, PlanRotorMotionRequest
import spherical_robots_testing as testing
from spherical_robots_testing import Recorder, quaternion_angle

PKG = 'spherical_robots'
WALL_DEADLINE = 150.0  # [s] wall, for the whole execution (about 14 s simulated)
RADIUS = 0.1           # [m], launch/rotor_stack.launch


# Every wait of this script is bounded by WALL_DEADLINE.
wait_until = functools.partial(testing.wait_until, timeout=WALL_DEADLINE)
sim_sleep = functools.partial(testing.sim_sleep, timeout=WALL_DEADLINE)
# A one-step manoeuvre with a published plan (Svinin et al., section IV: h = R along +v_a), for
# the preempt and cancel cases: 2 pi + 1 s of motion at 1 rad/s.
SHORT = dict(k=2.5, steps=1, u_a=0.0, v_a=RADIUS, psi=0.0)


class ManoeuvreClient(testing.GoalClient):
    """A client of rotor_planner/execute_manoeuvre."""

    def __init__(self):
        super().__init__('rotor_planner/execute_manoeuvre', ExecuteRotorManoeuvreAction,
                         WALL_DEADLINE)

    def execute(self, **fields):
        self.send(ExecuteRotorManoeuvreGoal(**fields))

    def wait_progress(self, fraction):
        """Until the feedback says that much of the manoeuvre is traced."""
        wait_until(lambda: self.feedback and self.feedback[-1].progress >= fraction,
                   '%.0f %% of the manoeuvre' % (100 * fraction))


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
        cls.diagnostics = Recorder('/diagnostics', DiagnosticArray)
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)

    def latest_status(self, suffix):
        """The latest /diagnostics status whose name ends with suffix, or None."""
        statuses = [s for a in self.diagnostics.since(0) for s in a.status if s.name.endswith(suffix)]
        return statuses[-1] if statuses else None

    def start_up_manoeuvre_done(self):
        """The planner says on /diagnostics that it is idle after one execution."""
        status = self.latest_status('rotor planner')
        values = {v.key: v.value for v in status.values} if status else {}
        return values.get('state') == 'idle' and int(values.get('executions', 0)) >= 1

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
            client = ManoeuvreClient()
            wall_start, sim_start = time.time(), rospy.Time.now().to_sec()
            client.execute(k=self.k, steps=self.steps, u_a=u, v_a=v, psi=psi, plan_index=0)
            state, result = client.result('the manoeuvre executed')
            self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
            self.assertEqual(result.status, ExecuteRotorManoeuvreResult.EXECUTED, result.message)
            # Feedback every command period: the plan traced to its end, then the settle.
            feedback = client.feedback
            self.assertGreater(len(feedback), 1000)
            self.assertEqual(feedback[0].state, 'executing')
            self.assertEqual(feedback[-1].state, 'settling')
            progress = [f.progress for f in feedback]
            self.assertEqual(progress, sorted(progress))
            self.assertLess(progress[0], 0.01)
            self.assertEqual(progress[-1], 1.0)
        else:
            wait_until(self.start_up_manoeuvre_done, 'the start-up manoeuvre (/diagnostics)')
            result = None
        done_at = rospy.Time.now()
        wall, sim = time.time() - wall_start, done_at.to_sec() - sim_start
        # odom comes on a connection of its own: wait for one from the end on.
        wait_until(lambda: self.odom.last().header.stamp >= done_at, 'odom after the end')
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
        if result is not None:  # the planner measured the same rest from odom
            self.assertAlmostEqual(result.distance, error, delta=1e-9)
        # Idle after a manoeuvre that ended normally is OK: the planner, and the hardware whose
        # watchdog then finds the rotors commanded to rest.
        wait_until(lambda: 'idle' in getattr(self.latest_status(': actuators'), 'message', ''),
                   'the hardware interface idle on /diagnostics')
        for suffix in (': actuators', 'rotor planner'):
            status = self.latest_status(suffix)
            self.assertEqual(status.level, DiagnosticStatus.OK, '%s: %s' % (status.name,
                                                                           status.message))
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


    def test_03_bad_goals_are_rejected_and_the_execution_in_force_goes_on(self):
        """An invalid request, a target without a plan and a plan_index beyond the plans, sent
        while a manoeuvre executes: each rejected at once with the reason, the manoeuvre goes on;
        then it is canceled."""
        if not rospy.get_param('~actions', False):
            return
        client, bad = ManoeuvreClient(), ManoeuvreClient()
        client.execute(plan_index=0, **SHORT)
        client.wait_progress(0.1)
        for fields, reason in ((dict(SHORT, steps=0), 'steps'),
                               (dict(SHORT, u_a=100.0 * RADIUS), 'no plan'),
                               (dict(SHORT, plan_index=99), 'plan_index 99')):
            bad.execute(**fields)
            state, result = bad.result('the rejection of %s' % fields)
            self.assertEqual(state, GoalStatus.REJECTED, result.message)
            self.assertEqual(result.status, ExecuteRotorManoeuvreResult.REJECTED, result.message)
            self.assertIn(reason, result.message)
        count = len(client.feedback)
        wait_until(lambda: len(client.feedback) > count + 10, 'feedback after the rejections')
        self.assertEqual(client.state(), GoalStatus.ACTIVE)
        client.cancel()
        self.assertEqual(client.result('the cancel')[0], GoalStatus.PREEMPTED)

    def test_04_a_second_goal_preempts_the_first(self):
        """A second goal while the first executes: the first preempted (its miss as measured),
        the rotors commanded to rest, the second executed."""
        if not rospy.get_param('~actions', False):
            return
        first, second = ManoeuvreClient(), ManoeuvreClient()
        first.execute(plan_index=0, **SHORT)
        first.wait_progress(0.3)
        sent = rospy.Time.now().to_sec()  # the step that takes the second goal comes later
        second.execute(plan_index=0, **SHORT)
        state, result = first.result('the first goal preempted')
        self.assertEqual(state, GoalStatus.PREEMPTED, result.message)
        self.assertEqual(result.status, ExecuteRotorManoeuvreResult.PREEMPTED, result.message)
        self.assertGreater(result.distance, 0.0)
        self.assertGreater(result.elapsed, 0.0)
        state, result = second.result('the second goal executed')
        self.assertEqual(state, GoalStatus.SUCCEEDED, result.message)
        self.assertEqual(result.status, ExecuteRotorManoeuvreResult.EXECUTED, result.message)
        # At the step that took the second goal a zero set-point (the rotors to rest; the
        # second's sin^2 ramps start at rest), then the second's set-points.
        commands = [c for c in self.commands.since(0) if c.header.stamp.to_sec() >= sent]
        moving = [any(v != 0.0 for v in c.velocity) for c in commands]
        rest = moving.index(False)
        self.assertTrue(any(moving[rest:]), 'no set-point of the second manoeuvre after the rest')

    def test_05_cancel_brings_the_rotors_to_rest(self):
        """A cancel while a manoeuvre executes: preempted, the last set-point zero, the rotors at
        rest and the sphere staying where it stopped."""
        if not rospy.get_param('~actions', False):
            return
        client = ManoeuvreClient()
        client.execute(plan_index=0, **SHORT)
        client.wait_progress(0.3)
        self.assertGreater(max(abs(v) for v in self.commands.last().velocity), 0.5)
        client.cancel()
        state, result = client.result('the cancel')
        self.assertEqual(state, GoalStatus.PREEMPTED, result.message)
        self.assertEqual(result.status, ExecuteRotorManoeuvreResult.PREEMPTED, result.message)
        sim_sleep(1.0)  # the rotors ramp down at the hardware's 300 rad/s^2
        self.assertEqual(list(self.commands.last().velocity), [0.0, 0.0])
        self.assertEqual(list(self.joints.last().velocity), [0.0, 0.0])
        before = self.odom.last().pose.pose.position
        sim_sleep(1.0)
        after = self.odom.last().pose.pose.position
        moved = math.hypot(after.x - before.x, after.y - before.y)
        print('rotor stack cancel: %.3f of the manoeuvre, %.3e m from its goal; then moved %.3g m'
              % (client.feedback[-1].progress, result.distance, moved))
        self.assertLess(moved, 1e-12)


if __name__ == '__main__':
    rostest.rosrun(PKG, 'rotor_stack_check', RotorStackCheck)
