#!/usr/bin/env python3
"""rostest of the FreeBOT stack (launch/freebot_stack.launch, test/freebot_stack.test), headless,
in simulated time, in the stack's namespace.

The goals go through freebot_ik's move_freebot action, with actionlib's own client: arrival
(succeeded, ARRIVED, the feedback on the way), an unreachable goal (aborted, nothing moves), a
goal preempted by a second one while it moves (preempted, the second arrives), a cancel while it
moves (preempted: the wheel commands go to zero and the chain stays put), a malformed goal
(rejected, the goal in force goes on).

Private params: ~frame_prefix; ~reachable ([x, y, z, qw, qx, qy, qz]: a full-pose goal the chain
reaches), ~position_only ([x, y, z]: a position it reaches), ~unreachable (a goal it cannot);
~position_bound [m], ~orientation_bound [rad] on the end-effector's tf after arrival;
~arrival_time [s] simulated; ~hold_bound [m] on how far the end-effector may move after an
unreachable verdict. The last test kills freebot_ik to fire the hardware's watchdog
(docs/hardware_interface.md): it needs ideal actuators (exact zeros).
"""
import functools
import math
import time
import unittest

import rospy
import rostest
import tf2_ros
from actionlib_msgs.msg import GoalStatus
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from geometry_msgs.msg import Pose
from sensor_msgs.msg import JointState
from std_srvs.srv import Empty, Trigger

from spherical_robots.msg import (FreebotState, MoveFreebotAction, MoveFreebotFeedback,
                                  MoveFreebotGoal, MoveFreebotResult)
from spherical_robots.srv import SolveFreebotIk
import spherical_robots_testing as testing
from spherical_robots_testing import Recorder, first_at_rest, quaternion_angle, silenced

PKG = 'spherical_robots'
NAME = 'freebot_stack_check'
WALL_DEADLINE = 240.0  # [s] wall, for anything the stack should do in time
IK_STATUS = 'freebot_ik: freebot ik'  # after the namespace: '<ns>/freebot_ik: freebot ik'
PLANT_STATUS = 'freebot_plant: freebot plant'
SLACK = 0.5  # [s] simulated: message latency at 5x real time (0.1 s of wall)


# Every wait of this script is bounded by WALL_DEADLINE.
wait_until = functools.partial(testing.wait_until, timeout=WALL_DEADLINE)
sim_sleep = functools.partial(testing.sim_sleep, timeout=WALL_DEADLINE)


def pose_of(values):
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = values[:3]
    if len(values) == 7:
        o = pose.orientation
        o.w, o.x, o.y, o.z = values[3:]
    return pose


def goal_of(values, frame):
    goal = MoveFreebotGoal()
    goal.target.header.frame_id = frame
    goal.target.header.stamp = rospy.Time.now()
    goal.target.pose = pose_of(values)
    return goal


class MoveClient(testing.GoalClient):
    """A client of move_freebot, whose goals are in the chain's fixed base frame."""

    def __init__(self, base_frame):
        super().__init__('move_freebot', MoveFreebotAction, WALL_DEADLINE)
        self.base_frame = base_frame

    def move(self, values):
        """A goal [x, y, z] or [x, y, z, qw, qx, qy, qz] in the base frame."""
        self.send(goal_of(values, self.base_frame))


class FreebotStackCheck(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        cls.prefix = rospy.get_param('~frame_prefix', rospy.get_namespace().strip('/') + '/')
        cls.radii = [float(r) for r in rospy.get_param('freebot/radii')]
        cls.modules = len(cls.radii) - 1
        cls.end_frame = cls.prefix + 'link%d' % cls.modules
        cls.base_frame = cls.prefix + 'link0'
        cls.reachable = [float(v) for v in rospy.get_param('~reachable')]
        cls.unreachable = [float(v) for v in rospy.get_param('~unreachable')]
        cls.states = Recorder('freebot_state', FreebotState)
        cls.actuators = Recorder('actuators/state', JointState)
        cls.diagnostics = Recorder('/diagnostics', DiagnosticArray)
        cls.tf_buffer = tf2_ros.Buffer()
        cls.tf_listener = tf2_ros.TransformListener(cls.tf_buffer)
        cls.commands = Recorder('actuators/command', JointState)
        wait_until(lambda: cls.states.count() > 0, 'the first freebot_state message')
        cls.goals = MoveClient(cls.base_frame)

    def end_effector(self):
        """B_n's centre and orientation (w, x, y, z) in the base's frame, from tf."""
        t = self.tf_buffer.lookup_transform(self.base_frame, self.end_frame, rospy.Time(0),
                                            rospy.Duration(10.0)).transform
        return ((t.translation.x, t.translation.y, t.translation.z),
                (t.rotation.w, t.rotation.x, t.rotation.y, t.rotation.z))

    def send(self, values, what='the verdict'):
        """Sends a goal and returns its final (state, result)."""
        self.goals.move(values)
        return self.goals.result(what)

    def wait_moving(self):
        """Until a wheel turns faster than 1 rad/s."""
        count = self.actuators.count()
        wait_until(lambda: any(abs(v) > 1.0 for m in self.actuators.since(count) for v in m.velocity),
                   'a wheel faster than 1 rad/s')

    def ik_status(self, since):
        return self.status(IK_STATUS, since)

    def status(self, suffix, since=0):
        statuses = [s for a in self.diagnostics.since(since) for s in a.status if s.name.endswith(suffix)]
        return statuses[-1] if statuses else None

    def value(self, suffix, key):
        status = self.status(suffix)
        return next((pair.value for pair in status.values if pair.key == key), None) if status else None

    def test_00_description_and_frames(self):
        """robot_description is the chain of freebot/radii, sphere for sphere; the fixed base is
        a frame of map (at the origin parameters, 0 by default), with no odometry."""
        import xml.etree.ElementTree as ElementTree
        robot = ElementTree.fromstring(rospy.get_param('robot_description'))
        spheres = {link.get('name'): float(link.find('collision/geometry/sphere').get('radius'))
                   for link in robot.findall('link')}
        self.assertEqual(spheres, {'link%d' % i: r for i, r in enumerate(self.radii)})
        base = self.tf_buffer.lookup_transform('map', self.base_frame, rospy.Time(0),
                                               rospy.Duration(10.0)).transform
        self.assertEqual((base.translation.x, base.translation.y, base.translation.z), (0.0, 0.0, 0.0))
        self.assertFalse(self.tf_buffer.can_transform('map', self.prefix + 'odom', rospy.Time(0)))

    def test_01_service(self):
        """solve_ik: the reachable target within the solver's default tolerances, the other not,
        with the closest pose's errors; nothing moves."""
        rospy.wait_for_service('solve_ik', timeout=60.0)
        solve = rospy.ServiceProxy('solve_ik', SolveFreebotIk)
        before = self.end_effector()[0]
        reply = solve(target=pose_of(self.reachable), position_only=False)
        self.assertTrue(reply.success, reply.message)
        self.assertLessEqual(reply.position_error, 1e-5)
        self.assertLessEqual(reply.orientation_error, 1e-4)
        self.assertEqual(len(reply.joint_quaternions), self.modules)
        reply = solve(target=pose_of(self.unreachable), position_only=True)
        self.assertFalse(reply.success, reply.message)
        # The closest point of a chain of reach R to a target at distance d > R is d - R away.
        d = math.sqrt(sum(v * v for v in self.unreachable[:3]))
        reach = sum(a + b for a, b in zip(self.radii[:-1], self.radii[1:]))
        self.assertAlmostEqual(reply.position_error, d - reach, delta=1e-4)
        sim_sleep(0.5)
        self.assertLess(math.dist(before, self.end_effector()[0]), 1e-9)

    def test_02_reachable(self):
        """A full-pose goal: the end-effector's tf arrives within the bounds, in time, and the
        spheres stay in contact (centre distances l_{i-1} + l_i)."""
        start = rospy.Time.now().to_sec()
        before = self.end_effector()[0]
        state, verdict = self.send(self.reachable)
        self.assertEqual(state, GoalStatus.SUCCEEDED, verdict.message)
        self.assertEqual(verdict.status, MoveFreebotResult.ARRIVED, verdict.message)
        # The feedback on the way: moving, from the chain at rest (its first step's measurement)
        # to the arrival, the time since the goal growing.
        feedback = self.goals.feedback
        self.assertGreater(len(feedback), 100)
        self.assertTrue(all(f.status == MoveFreebotFeedback.MOVING for f in feedback))
        self.assertAlmostEqual(feedback[0].position_error, math.dist(before, self.reachable[:3]),
                               delta=1e-9)
        self.assertEqual([f.elapsed for f in feedback], sorted(f.elapsed for f in feedback))
        self.assertLess(feedback[-1].position_error, 0.01 * feedback[0].position_error)
        sim_sleep(0.2)  # tf at 50 Hz
        position, orientation = self.end_effector()
        position_error = math.dist(position, self.reachable[:3])
        orientation_error = quaternion_angle(orientation, self.reachable[3:])
        rospy.loginfo('arrived after %.2f s (simulated): %.3g m, %.3g rad from the goal (tf)',
                      verdict.elapsed, position_error, orientation_error)
        self.assertLessEqual(position_error, float(rospy.get_param('~position_bound')))
        self.assertLessEqual(orientation_error, float(rospy.get_param('~orientation_bound')))
        self.assertLessEqual(verdict.elapsed, float(rospy.get_param('~arrival_time')))
        self.assertLessEqual(rospy.Time.now().to_sec() - start,
                             float(rospy.get_param('~arrival_time')) + 1.0)
        for i in range(1, self.modules + 1):
            t = self.tf_buffer.lookup_transform(self.prefix + 'link%d' % (i - 1),
                                                self.prefix + 'link%d' % i, rospy.Time(0)).transform
            distance = math.sqrt(t.translation.x ** 2 + t.translation.y ** 2 + t.translation.z ** 2)
            self.assertAlmostEqual(distance, self.radii[i - 1] + self.radii[i], delta=1e-9)

    def test_03_position_only(self):
        """A goal with an all-zero orientation: B_n's centre arrives, whatever its orientation."""
        target = [float(v) for v in rospy.get_param('~position_only')]
        state, verdict = self.send(target)
        self.assertEqual(state, GoalStatus.SUCCEEDED, verdict.message)
        self.assertEqual(verdict.status, MoveFreebotResult.ARRIVED, verdict.message)
        self.assertEqual(verdict.orientation_error, 0.0)
        sim_sleep(0.2)
        position_error = math.dist(self.end_effector()[0], target)
        rospy.loginfo('position only: arrived after %.2f s (simulated), %.3g m from the goal (tf)',
                      verdict.elapsed, position_error)
        self.assertLessEqual(position_error, float(rospy.get_param('~position_bound')))
        self.assertLessEqual(verdict.elapsed, float(rospy.get_param('~arrival_time')))

    def test_04_unreachable(self):
        """A goal out of reach: aborted with a clear verdict (UNREACHABLE, /diagnostics WARN) and
        nothing moves: the wheels stay at rest and the end-effector holds its pose."""
        before = self.end_effector()[0]
        diagnostics_index = self.diagnostics.count()
        actuators_index = self.actuators.count()
        state, verdict = self.send(self.unreachable)
        self.assertEqual(state, GoalStatus.ABORTED, verdict.message)
        self.assertEqual(verdict.status, MoveFreebotResult.UNREACHABLE, verdict.message)
        self.assertIn('unreachable', verdict.message)
        self.assertIn('beyond the reach', verdict.message)
        self.assertGreater(verdict.position_error, 0.0)
        wait_until(lambda: self.ik_status(diagnostics_index) is not None and
                   self.ik_status(diagnostics_index).level == DiagnosticStatus.WARN,
                   'freebot_ik to report WARN on /diagnostics')
        self.assertIn('unreachable', self.ik_status(diagnostics_index).message)
        sim_sleep(3.0)
        fastest = max((abs(v) for m in self.actuators.since(actuators_index) for v in m.velocity),
                      default=0.0)
        moved = math.dist(before, self.end_effector()[0])
        rospy.loginfo('after the unreachable goal: fastest wheel %.3g rad/s, end-effector moved '
                      '%.3g m', fastest, moved)
        self.assertGreater(self.actuators.count(), actuators_index + 100)
        self.assertLess(fastest, 1e-9)
        self.assertLess(moved, float(rospy.get_param('~hold_bound')))

    def test_05_a_second_goal_preempts_the_first(self):
        """A second goal while the first moves: the first is preempted (its errors as measured),
        the second arrives."""
        second = MoveClient(self.base_frame)
        self.goals.move(self.reachable)
        self.wait_moving()
        target = [float(v) for v in rospy.get_param('~position_only')]
        second.move(target)
        state, verdict = self.goals.result('the first goal preempted')
        self.assertEqual(state, GoalStatus.PREEMPTED, verdict.message)
        self.assertEqual(verdict.status, MoveFreebotResult.PREEMPTED, verdict.message)
        self.assertGreater(verdict.position_error, float(rospy.get_param('~position_bound')))
        self.assertGreater(verdict.elapsed, 0.0)
        state, verdict = second.result('the second goal to arrive')
        self.assertEqual(state, GoalStatus.SUCCEEDED, verdict.message)
        self.assertEqual(verdict.status, MoveFreebotResult.ARRIVED, verdict.message)
        sim_sleep(0.2)
        self.assertLessEqual(math.dist(self.end_effector()[0], target),
                             float(rospy.get_param('~position_bound')))

    def test_06_cancel_stops_the_chain(self):
        """A cancel while the chain moves: preempted; from the step that took it every wheel
        command is zero, and once the wheels have stopped the chain stays put."""
        self.goals.move(self.reachable)
        self.wait_moving()
        self.goals.cancel()
        state, verdict = self.goals.result('the canceled goal to end')
        self.assertEqual(state, GoalStatus.PREEMPTED, verdict.message)
        self.assertEqual(verdict.status, MoveFreebotResult.PREEMPTED, verdict.message)
        ended = rospy.Time.now().to_sec()
        sim_sleep(1.0)  # the wheels ramp down at the hardware's 50 rad/s^2 (0.2 s from 10 rad/s)
        before = self.end_effector()[0]
        commands = [(c.header.stamp.to_sec(), c.velocity) for c in self.commands.since(0)]
        moving = [t for t, velocity in commands if any(v != 0.0 for v in velocity)]
        after = [velocity for t, velocity in commands if t > moving[-1]]
        sim_sleep(1.0)
        moved = math.dist(before, self.end_effector()[0])
        rospy.loginfo('cancel: the last moving command at %.2f s, the result received at %.2f s '
                      '(simulated); then %d zero commands; the end-effector moved %.3g m',
                      moving[-1], ended, len(after), moved)
        self.assertLessEqual(moving[-1], ended)
        self.assertGreater(len(after), 50)  # 100 Hz: the zeros went on
        self.assertLess(moved, 1e-12)

    def test_07_a_malformed_goal_is_rejected_and_the_goal_in_force_goes_on(self):
        """A goal with a NaN coordinate while another moves: rejected at once, naming the field;
        the goal in force arrives."""
        bad = MoveClient(self.base_frame)
        self.goals.move(self.reachable)
        self.wait_moving()
        bad.move([float('nan')] + list(self.reachable[1:]))
        state, verdict = bad.result('the malformed goal rejected')
        self.assertEqual(state, GoalStatus.REJECTED, verdict.message)
        self.assertEqual(verdict.status, MoveFreebotResult.REJECTED, verdict.message)
        self.assertIn('target.pose.position', verdict.message)
        self.assertEqual(verdict.position_error, -1.0)
        state, verdict = self.goals.result('the goal in force to arrive')
        self.assertEqual(state, GoalStatus.SUCCEEDED, verdict.message)
        self.assertEqual(verdict.status, MoveFreebotResult.ARRIVED, verdict.message)

    def test_08_bad_measurements_kill_nothing(self):
        """A NaN and an incomplete actuators/state are rejected, counted on /diagnostics, and the
        plant keeps publishing."""
        publisher = rospy.Publisher('actuators/state', JointState, queue_size=10)
        names = ['module%d_wheel_%s' % (i, side) for i in range(1, self.modules + 1)
                 for side in ('right', 'left')]
        bad_nan = JointState(name=names, velocity=[float('nan')] + [0.0] * (len(names) - 1))
        bad_missing = JointState(name=names[1:], velocity=[0.0] * (len(names) - 1))
        key = rospy.resolve_name('actuators/state') + ' rejected'
        testing.publish_until(publisher, [bad_nan, bad_missing],
                              lambda: int(self.value(PLANT_STATUS, key) or 0) >= 2,
                              'the plant to report 2 rejections', WALL_DEADLINE)
        count = self.states.count()
        sim_sleep(1.0)
        self.assertGreater(self.states.count(), count + 50, 'freebot_state stopped')
        self.assertTrue(all(math.isfinite(v) for v in self.end_effector()[0]))

    def test_09_watchdog_when_ik_goes_silent(self):
        """freebot_ik stopped mid-motion (SIGSTOP: silent, neither dead, which would end the stack
        or restart the node, nor answering): the hardware's watchdog brings every wheel to rest
        within command_timeout + |v|/max_acceleration + one period of the last command, and the
        chain stops."""
        hardware = rospy.resolve_name('hardware_interface')
        timeout = float(rospy.get_param(hardware + '/command_timeout'))
        acceleration = float(rospy.get_param(hardware + '/max_acceleration'))
        period = 1.0 / float(rospy.get_param(hardware + '/rate'))
        commands = Recorder('actuators/command', JointState)
        # Time held, and stepped one step at a time until a wheel turns, so that freebot_ik falls
        # silent mid-motion however far the loop would have run ahead of this node (an observer,
        # which the loop does not wait for): on a busy machine the goal was once reached before
        # the silence began.
        lockstep = {name: rospy.ServiceProxy('lockstep/' + name, kind) for name, kind in
                    (('pause', Empty), ('step_once', Trigger), ('resume', Empty))}
        lockstep['pause']()
        time.sleep(0.2)  # [s] of wall time: the held step's messages reach this node
        count = self.actuators.count()
        self.goals.move(self.reachable)
        for _ in range(500):
            if any(abs(v) > 1.0 for m in self.actuators.since(count) for v in m.velocity):
                break
            self.assertTrue(lockstep['step_once']().success, 'lockstep/step_once refused')
            time.sleep(0.02)  # [s] of wall time for the step's actuator state
        else:
            self.fail('no wheel faster than 1 rad/s after 500 single steps')
        speed = max(abs(v) for v in self.actuators.since(-1)[0].velocity)
        with silenced(rospy.resolve_name('freebot_ik')):
            lockstep['resume']()
            wait_until(lambda: commands.count() > 0, 'a recorded command')
            last_command = commands.timed_since(0)[-1][0]
            wait_until(lambda: first_at_rest(self.actuators, last_command) is not None,
                       'every wheel at rest')
            at_rest = (first_at_rest(self.actuators, last_command).header.stamp.to_sec()
                       - last_command)
            bound = timeout + speed / acceleration + period
            sim_sleep(0.5)
            before = self.end_effector()[0]
            sim_sleep(1.0)
            moved = math.dist(before, self.end_effector()[0])
        rospy.loginfo('watchdog: wheels at rest %.3f s (simulated) after the last command (bound '
                      '%.3f s from %.2f rad/s), then the end-effector moved %.3g m', at_rest,
                      bound, speed, moved)
        self.assertLess(at_rest, bound + SLACK)
        self.assertGreater(at_rest, timeout - SLACK, 'the watchdog fired early')
        self.assertLess(moved, 1e-12)

if __name__ == '__main__':
    rospy.init_node(NAME)
    rostest.rosrun(PKG, NAME, FreebotStackCheck)
