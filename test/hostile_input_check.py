#!/usr/bin/env python3
"""Hostile input against a running stack, from a table of cases (rostest).

For every subscribed topic of the stack's loop it sends bursts of bad messages -- NaN, +-Inf,
+-1e300, empty and mis-sized arrays, unknown and duplicated names, zero and non-unit vectors,
stamps at 0, in the past and in the future -- and one stray /clock 1,000 s ahead. After each
burst: no node of the stack has died, no message the stack published (on any topic of its
namespace, /tf) holds a non-finite number, and the stack tracks again within `~recovery` [s] of
simulated time (the tracking error below `~error_bound`; with `~batch`, below the undisturbed batch
run's error at the same simulated time plus `~error_bound`). During a burst into the hardware
interface its /diagnostics must leave OK (it escalates on rejections), and return to OK after it.

The rotor and FreeBOT stacks have no tracking error: there the stack's goal is checked once at
the end instead (the manoeuvre ends at its target; the FreeBOT goal is ARRIVED, never ABORTED).

Private parameters: ~stack (terrain | roller | norma | rotor | freebot), ~error_bound [m] (terrain,
roller, Norma: tracking; rotor: distance of the rest to ~target), ~recovery [s] of simulated time
(2), ~burst [s] of wall time per case (0.2, at ~500 messages per second), ~nodes (the node names
that must survive), ~target (rotor: "u,v,psi" [m, m, rad]), ~batch (Norma: the `sphere_sim norma
--loop sampled` arguments of the stack's own undisturbed run, e.g. "--controller tracking"; its
tracking error swings up to 0.22 m by itself, t = 98-140 s, so a fixed bound passes or fails with
how far the test has got by then). Run in the stack's namespace.
"""
import bisect
import copy
import csv
import math
import os
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import rosgraph
import roslib.packages
import rosnode
import rospy
import rostest
import rostopic
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import JointState

from spherical_robots.msg import (ExecuteRotorManoeuvreAction, ExecuteRotorManoeuvreGoal,
                                  FreebotState, MoveFreebotAction, MoveFreebotActionGoal,
                                  MoveFreebotGoal, MoveFreebotResult, TrackingError)
from spherical_robots_testing import GoalClient, wait_until

NAN = float('nan')
INF = float('inf')
HUGE = 1e300
RATE = 500.0  # [1/s] of wall time


def non_finite_field(msg, path=''):
    """The path of the first non-finite float in msg (recursively), or None."""
    if isinstance(msg, float):
        return None if math.isfinite(msg) else path or '.'
    if isinstance(msg, (list, tuple)):
        for i, item in enumerate(msg):
            found = non_finite_field(item, '%s[%d]' % (path, i))
            if found:
                return found
        return None
    if hasattr(msg, '__slots__'):
        for slot in msg.__slots__:
            found = non_finite_field(getattr(msg, slot), path + '.' + slot)
            if found:
                return found
    return None


def joint_state_cases(names, field):
    """Bad JointStates for actuators `names`, values in `field` (velocity or effort)."""
    def make(values=None, name=None, stamp=None, sizes=None):
        msg = JointState()
        msg.header.stamp = rospy.Time.now() if stamp is None else stamp
        msg.name = list(names if name is None else name)
        good = [0.1] * len(msg.name)
        setattr(msg, field, list(good if values is None else values))
        return msg
    count = len(names)
    now = rospy.Time.now()
    return [
        ('NaN', make([NAN] * count)),
        ('+Inf', make([INF] * count)),
        ('-Inf', make([-INF] * count)),
        ('+1e300', make([HUGE] * count)),
        ('-1e300', make([-HUGE] * count)),
        ('empty', make([], [])),
        ('mis-sized', make([0.1] * (count - 1))),
        ('unknown names', make(name=['no_such_actuator'] * count)),
        ('duplicated names', make(name=[names[0]] * count)),
        ('stamp 0, NaN', make([NAN] * count, stamp=rospy.Time(0))),
        ('stamp in the future, 1e300', make([HUGE] * count, stamp=now + rospy.Duration(1000.0))),
    ]


def stamped_copies(last, label):
    """The last good state with stamps at 0, 100 s in the past and 1,000 s in the future."""
    cases = []
    for name, stamp in (('stamp 0', rospy.Time(0)),
                        ('stamp in the past', last.header.stamp - rospy.Duration(100.0)
                         if last.header.stamp.to_sec() > 100.0 else rospy.Time(1)),
                        ('stamp in the future', last.header.stamp + rospy.Duration(1000.0))):
        msg = copy.deepcopy(last)
        msg.header.stamp = stamp
        cases.append(('%s %s' % (label, name), msg))
    return cases


def edited_copies(last, edits):
    """Copies of the last good message, stamped now, each with one bad edit."""
    cases = []
    for label, edit in edits:
        msg = copy.deepcopy(last)
        msg.header.stamp = rospy.Time.now()
        edit(msg)
        cases.append((label, msg))
    return cases


def odometry_cases(last):
    def orientation(x, y, z, w):
        def edit(m):
            m.pose.pose.orientation.x, m.pose.pose.orientation.y = x, y
            m.pose.pose.orientation.z, m.pose.pose.orientation.w = z, w
        return edit
    return edited_copies(last, (
        ('odom position NaN', lambda m: setattr(m.pose.pose.position, 'x', NAN)),
        ('odom position 1e300', lambda m: setattr(m.pose.pose.position, 'y', HUGE)),
        ('odom zero quaternion', orientation(0.0, 0.0, 0.0, 0.0)),
        ('odom non-unit quaternion', orientation(0.0, 0.0, 0.0, 3.0)),
        ('odom twist Inf', lambda m: setattr(m.twist.twist.linear, 'x', INF)),
    )) + stamped_copies(last, 'odom')


def freebot_state_cases(last):
    def link(i, x, y, z, w):
        def edit(m):
            m.link = list(m.link)
            m.link[i] = copy.deepcopy(m.link[i])
            m.link[i].x, m.link[i].y, m.link[i].z, m.link[i].w = x, y, z, w
        return edit
    return edited_copies(last, (
        ('link NaN', link(0, NAN, 0.0, 0.0, 1.0)),
        ('link zero quaternion', link(1, 0.0, 0.0, 0.0, 0.0)),
        ('link non-unit', link(2, 0.0, 0.0, 0.0, 2.0)),
        ('heading 1e300', lambda m: setattr(m, 'heading', [HUGE] * len(m.heading))),
        ('mis-sized arrays', lambda m: setattr(m, 'base', list(m.base)[:-1])),
        ('empty arrays', lambda m: (setattr(m, 'link', []), setattr(m, 'base', []))),
    )) + stamped_copies(last, 'freebot_state')


def goal_cases(_last):
    """Malformed goals of the move_freebot action, as a client's goal topic carries them. The
    action server takes a goal id once (a repeat is the same goal): one id per case."""
    def goal(x, y, z, qw=1.0, frame='freebot/link0'):
        msg = MoveFreebotActionGoal()
        msg.header.stamp = msg.goal_id.stamp = rospy.Time.now()
        msg.goal_id.id = 'hostile %r %r %r %r %s' % (x, y, z, qw, frame)
        target = msg.goal.target
        target.header.frame_id = frame
        target.header.stamp = rospy.Time.now()
        target.pose.position.x, target.pose.position.y, target.pose.position.z = x, y, z
        target.pose.orientation.w = qw
        return msg
    return [('goal NaN', goal(NAN, 0.1, 0.1)), ('goal 1e300', goal(HUGE, 0.1, 0.1)),
            ('goal -Inf', goal(0.1, -INF, 0.1)), ('goal non-unit', goal(0.1, 0.1, 0.1, 5.0)),
            ('goal in an unknown frame', goal(0.1, 0.1, 0.1, 1.0, 'nowhere'))]


def wheel_names(modules):
    return ['module%d_wheel_%s' % (i, side) for i in range(1, modules + 1)
            for side in ('right', 'left')]


# Per stack: the JointState topics it reads (topic, actuator names, value field), its other
# inputs (topic, type, cases from the last good message seen there; None: no message needed),
# and whether it publishes tracking_error.
STACKS = {
    'terrain': {
        'joint_topics': [('actuators/state', ['theta', 'phi', 'psi'], 'velocity'),
                         ('actuators/command', ['theta', 'phi', 'psi'], 'velocity')],
        'states': [('odom', Odometry, odometry_cases)],
        'tracking': True,
    },
    'roller': {
        'joint_topics': [('drive/state', ['theta', 'phi'], 'velocity'),
                         ('drive/command', ['theta', 'phi'], 'velocity'),
                         ('actuators/state', ['roller_1', 'roller_2'], 'velocity'),
                         ('actuators/command', ['roller_1', 'roller_2'], 'velocity')],
        'states': [('odom', Odometry, odometry_cases)],
        'tracking': True,
    },
    'norma': {
        # joint_states without positions: robot_state_publisher, which reads them too, drops
        # them whole (it would put a NaN position on /tf).
        'joint_topics': [('actuators/state', ['pendulum_motor', 'slider_motor'], 'effort'),
                         ('actuators/command', ['pendulum_motor', 'slider_motor'], 'effort'),
                         ('joint_states', ['tilt_joint', 'shell_joint', 'pendulum_joint',
                                           'slider_joint'], 'velocity')],
        'states': [('odom', Odometry, odometry_cases)],
        'tracking': True,
    },
    'rotor': {
        'joint_topics': [('actuators/state', ['rotor_1', 'rotor_2'], 'velocity'),
                         ('actuators/command', ['rotor_1', 'rotor_2'], 'velocity')],
        'states': [('odom', Odometry, odometry_cases)],
        'tracking': False,
    },
    'freebot': {
        'joint_topics': [('actuators/state', wheel_names(4), 'velocity'),
                         ('actuators/command', wheel_names(4), 'velocity')],
        'states': [('freebot_state', FreebotState, freebot_state_cases),
                   ('move_freebot/goal', MoveFreebotActionGoal, goal_cases, False)],
        'tracking': False,
    },
}


BATCH_DURATION = 1200.0  # [s] simulated: the test, uncapped (about 2x), ends at 150-300 s


class BatchError:
    """|e| of the stack's undisturbed batch run (sphere_sim norma --loop sampled ARGS), by time
    since the first step, which in lock-step is the stack's first stamp, one step after 0."""

    def __init__(self, args):
        out = os.path.join(tempfile.mkdtemp(prefix='hostile_input_batch.'), 'run.csv')
        sim = roslib.packages.find_node('spherical_robots', 'sphere_sim')[0]
        subprocess.run([sim, 'norma', '--loop', 'sampled'] + args.split()
                       + ['--duration', str(BATCH_DURATION), '--log-rate', '100', '--out', out],
                       check=True, stdout=subprocess.DEVNULL)
        with open(out) as f:
            rows = [(float(r['t']), float(r['err'])) for r in csv.DictReader(f)]
        os.remove(out)
        self.times = [t for t, _ in rows]
        self.errors = [e for _, e in rows]
        self.step = float(rospy.get_param('norma_plant/step'))

    def at(self, stamp):
        """The largest batch |e| within 0.02 s of stamp [s] (the log is at 100 Hz; the stamp's
        alignment is then no matter)."""
        t = stamp - self.step
        if t > self.times[-1]:
            raise AssertionError('the test ran past the batch run\'s %g s' % BATCH_DURATION)
        lo = bisect.bisect_left(self.times, t - 0.02)
        hi = bisect.bisect_right(self.times, t + 0.02)
        return max(self.errors[lo:hi]) if hi > lo else self.errors[min(lo, len(self.errors) - 1)]


class HostileInput(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('hostile_input_check')
        cls.stack = rospy.get_param('~stack')
        cls.spec = STACKS[cls.stack]
        cls.error_bound = float(rospy.get_param('~error_bound'))
        batch_args = rospy.get_param('~batch', '')
        cls.batch = BatchError(batch_args) if batch_args else None
        cls.recovery = float(rospy.get_param('~recovery', 2.0))
        cls.burst = float(rospy.get_param('~burst', 0.2))
        cls.nodes = [rospy.resolve_name(n) for n in rospy.get_param('~nodes')]
        cls.lock = threading.Lock()
        cls.non_finite = []  # (topic, field)
        cls.errors = []      # (simulated time, |e|)
        cls.hardware_levels = []  # (wall time, level) of the hardware interface's status
        cls.last_hardware_status = None
        if cls.spec['tracking']:
            rospy.Subscriber('tracking_error', TrackingError, cls.on_error, queue_size=100)
        rospy.Subscriber('/diagnostics', DiagnosticArray, cls.on_diagnostics, queue_size=100)
        cls.last_state = {}
        for topic, msg_type, *_ in cls.spec['states']:
            rospy.Subscriber(topic, msg_type, cls.on_state, callback_args=topic, queue_size=10)
        if cls.stack == 'rotor':
            cls.start_manoeuvre()
        if cls.stack == 'freebot':
            cls.send_goal()
        cls.watched = set()
        cls.watch_timer = rospy.Timer(rospy.Duration(0.5), cls.watch_new_topics)
        wait_until(lambda: len(cls.watched) > 3, 'the stack to publish', 60.0)

    @classmethod
    def start_manoeuvre(cls):
        """Plans ~target and executes it (execute_manoeuvre): the bursts arrive while the rotors
        drive it."""
        u, v, psi = (float(x) for x in str(rospy.get_param('~target')).split(','))
        cls.target = (u, v)
        cls.goal = GoalClient('rotor_planner/execute_manoeuvre', ExecuteRotorManoeuvreAction, 60.0)
        cls.goal.send(ExecuteRotorManoeuvreGoal(k=2.5, steps=2, u_a=u, v_a=v, psi=psi))

    @classmethod
    def send_goal(cls):
        """Table II's C (reachable as a full pose with 4 modules), driven while the bursts come."""
        goal = MoveFreebotGoal()
        goal.target.header.frame_id = 'freebot/link0'
        position, q = goal.target.pose.position, goal.target.pose.orientation
        position.x, position.y, position.z = 0.0924, 0.1597, 0.1154
        q.w, q.x, q.y, q.z = 0.9682, 0.0874, 0.2220, 0.0756
        cls.goal = GoalClient('move_freebot', MoveFreebotAction, 120.0)
        wait_until(lambda: 'freebot_state' in cls.last_state, 'a chain state', 30.0)
        goal.target.header.stamp = rospy.Time.now()
        cls.goal.send(goal)
        wait_until(lambda: cls.goal.feedback, 'the goal to be taken (feedback)', 30.0)

    @classmethod
    def watch_new_topics(cls, _event=None):
        """Subscribes to every topic of the namespace (and /tf) that appears, to scan them."""
        ns = rospy.get_namespace()
        try:
            topics = rospy.get_published_topics()
        except Exception:  # the master is going away at the end of the test
            return
        for topic, _type in topics:
            if topic in cls.watched or not (topic.startswith(ns) or topic == '/tf'):
                continue
            msg_class, _, _ = rostopic.get_topic_class(topic)
            if msg_class is None:
                continue
            cls.watched.add(topic)
            rospy.Subscriber(topic, msg_class, cls.scan, callback_args=topic, queue_size=1000)

    @classmethod
    def scan(cls, msg, topic):
        if msg._connection_header.get('callerid') == rospy.get_name():
            return  # our own hostile messages
        field = non_finite_field(msg)
        if field:
            with cls.lock:
                cls.non_finite.append((topic, field))

    @classmethod
    def on_error(cls, msg):
        with cls.lock:  # by the sample's own stamp: a busy test node reads it late
            cls.errors.append((msg.header.stamp.to_sec(), msg.error_norm))

    @classmethod
    def on_state(cls, msg, topic):
        # Only the stack's own (finite, plausible) messages count, not this node's copies.
        if msg._connection_header.get('callerid') != rospy.get_name() \
                and non_finite_field(msg) is None and msg.header.stamp.to_sec() > 0.0 \
                and abs((msg.header.stamp - rospy.Time.now()).to_sec()) < 1.0 \
                and max(abs(v) for v in _numbers(msg)) < 1e6:
            cls.last_state[topic] = msg

    @classmethod
    def on_diagnostics(cls, msg):
        for status in msg.status:
            if status.name.endswith(': actuators'):
                cls.last_hardware_status = status
                with cls.lock:
                    cls.hardware_levels.append((time.time(), ord(status.level)
                                                if isinstance(status.level, bytes)
                                                else status.level))

    # --- helpers ---------------------------------------------------------------------------------

    def burst_of(self, publisher, messages, duration=None, pick=None):
        """Publishes the messages round-robin (or pick(k) as the k-th) at RATE for `duration`
        (self.burst) seconds of wall time. Paced by the clock, not by sleeps: a node descheduled
        for a while on a busy machine catches up, so the burst holds RATE * duration messages."""
        start = time.time()
        end = start + (self.burst if duration is None else duration)
        k = 0
        while True:
            now = time.time()
            due = int((min(now, end) - start) * RATE)
            while k < due:
                publisher.publish(pick(k) if pick else messages[k % len(messages)])
                k += 1
            if now >= end:
                return k
            time.sleep(0.005)

    def run_cases(self, publisher, cases):
        """A burst of each (label, message) case, then the checks after it."""
        for label, msg in cases:
            sent = self.burst_of(publisher, [msg])
            rospy.loginfo('%s: %d messages', label, sent)
            self.assert_nothing_died_or_went_non_finite(label)
            self.assert_tracks_again(label)
        publisher.unregister()

    def bound_at(self, stamp):
        """[m] the error bound at stamp [s]: ~error_bound, over the batch run's |e| with ~batch."""
        return self.error_bound + (self.batch.at(stamp) if self.batch else 0.0)

    def assert_tracks_again(self, what):
        """The tracking error is below the bound within self.recovery s of simulated time."""
        if not self.spec['tracking']:
            return  # checked once, at the end: test_5_goal_reached
        # The stack's own time, from its latest sample: this node's clock is jumped by a stray
        # /clock too.
        with self.lock:
            start = self.errors[-1][0]
        end = start + self.recovery

        # Done at the first sample after the burst within the bound, or once the stack is past
        # the recovery time without one: waiting out the whole recovery time for every case
        # kept an uncapped stack running, and this node scanning its messages, for nothing.
        def settled():
            with self.lock:
                return self.errors[-1][0] >= end or any(
                    e < self.bound_at(t) for t, e in self.errors[-50:] if start < t <= end)
        wait_until(settled, 'a tracking error stamped %.1f s after %s' % (self.recovery, what),
                   60.0)
        with self.lock:
            window = [(t, e) for t, e in self.errors if start < t <= end]
        after = [e for _, e in window]
        below = [t for t, e in window if e < self.bound_at(t)]
        if below:
            excess = ('; largest excess over the batch run %.4f m'
                      % max(e - self.batch.at(t) for t, e in window)) if self.batch else ''
            rospy.loginfo('%s: |e| below the bound %.2f s (simulated) after the burst, max |e| '
                          '%.4f m%s', what, below[0] - start, max(after), excess)
        self.assertTrue(below, 'after %s the stack does not track within %.1f s of simulated time: '
                        '|e| %s (bound %g m%s)' % (what, self.recovery, after[-5:], self.error_bound,
                                                   ' over the batch run\'s' if self.batch else ''))

    def assert_nothing_died_or_went_non_finite(self, what):
        for node in self.nodes:
            self.assertTrue(rosnode.rosnode_ping(node, max_count=1), '%s died after %s'
                            % (node, what))
        with self.lock:
            self.assertEqual(self.non_finite, [], 'non-finite numbers published after %s: %s'
                             % (what, self.non_finite[:5]))

    def wait_for_tracking(self):
        if not self.spec['tracking']:
            return
        wait_until(lambda: self.errors and self.errors[-1][1] < self.bound_at(self.errors[-1][0]),
                   'the stack to track within %g m' % self.error_bound, 120.0)

    # --- the cases ------------------------------------------------------------------------------

    def test_1_actuator_inputs(self):
        """Bad actuator states into the plant and bad commands into the hardware interface."""
        self.wait_for_tracking()
        for topic, names, field in self.spec['joint_topics']:
            publisher = rospy.Publisher(topic, JointState, queue_size=1000)
            wait_until(lambda: publisher.get_num_connections() > 1, 'subscribers of ' + topic, 20.0)
            self.run_cases(publisher, [('%s on %s' % (label, topic), msg)
                                       for label, msg in joint_state_cases(names, field)])

    def test_2_state_inputs(self):
        """Bad state messages into the controller; then the stamped copies of a good one."""
        self.wait_for_tracking()
        for topic, msg_type, cases, *needs_last in self.spec['states']:
            needs_last = not needs_last or needs_last[0]
            if needs_last:
                wait_until(lambda: topic in self.last_state, 'a state on ' + topic, 20.0)
            publisher = rospy.Publisher(topic, msg_type, queue_size=1000)
            # The stack's own publisher and this node's subscriber, or (goal) the IK alone.
            wait_until(lambda: publisher.get_num_connections() >= (2 if needs_last else 1),
                       'subscribers of ' + topic, 20.0)
            self.run_cases(publisher, cases(self.last_state.get(topic)))

    def test_3_stray_clock(self):
        """One /clock 1,000 s ahead: a jump, not 1,000 s of elapsed time or a frozen clock."""
        self.wait_for_tracking()
        publisher = rospy.Publisher('/clock', Clock, queue_size=10)
        wait_until(lambda: publisher.get_num_connections() > 1, 'subscribers of /clock', 20.0)
        stray = Clock()
        stray.clock = rospy.Time.now() + rospy.Duration(1000.0)
        publisher.publish(stray)
        time.sleep(0.1)
        publisher.unregister()
        self.assert_nothing_died_or_went_non_finite('a stray /clock')
        self.assert_tracks_again('a stray /clock')
        # Still tracking well after it: the hardware did not freeze until the clock came back.
        time.sleep(1.0)
        self.assert_tracks_again('a stray /clock, a second later')

    def test_4_diagnostics_escalate(self):
        """A burst of rejected commands raises the hardware interface's status; it comes back."""
        self.wait_for_tracking()
        _, names, field = next(t for t in self.spec['joint_topics']
                               if t[0] == 'actuators/command')
        publisher = rospy.Publisher('actuators/command', JointState, queue_size=1000)
        wait_until(lambda: publisher.get_num_connections() > 1, 'the hardware interface', 20.0)
        # The rotor planner commands only while it executes: once the manoeuvre is over this
        # test sends the good (zero) commands itself, one in five, and for 3 s after the burst.
        own_good = self.stack == 'rotor'
        if own_good:
            wait_until(self.goal.done, 'the manoeuvre to end', 120.0)
        good = JointState(name=list(names))
        setattr(good, field, [0.0] * len(names))
        start = time.time()
        bad = joint_state_cases(names, field)[0][1]
        # 3 s: long enough for two of the updater's 1 s reports.
        self.burst_of(publisher, [], 3.0, lambda k: good if own_good and k % 5 == 0 else bad)
        # Statuses published during the burst may be read late on a busy machine: wait for them.
        def escalated():
            with self.lock:
                return any(t > start + 0.5 and level == DiagnosticStatus.ERROR
                           for t, level in self.hardware_levels)
        try:
            wait_until(escalated, 'ERROR from the hardware interface', 10.0)
        except AssertionError:
            with self.lock:
                seen = [(round(t - start, 2), level) for t, level in self.hardware_levels]
            self.fail('the hardware status did not reach ERROR under %.0f rejected commands/s; its '
                      'statuses (s from the burst, level): %s; last: %s'
                      % (RATE, seen[-12:], self.last_hardware_status))
        ok_again = time.time()
        while own_good and time.time() < ok_again + 3.5:
            publisher.publish(good)
            time.sleep(0.05)
        try:
            wait_until(lambda: any(t > ok_again and level == DiagnosticStatus.OK
                                   for t, level in list(self.hardware_levels)),
                       'the hardware status back at OK after the burst', 20.0)
        except AssertionError as e:
            with self.lock:
                raise AssertionError('%s; levels since: %s; last: %s' % (
                    e, [level for t, level in self.hardware_levels if t > ok_again],
                    self.last_hardware_status))

    def test_5_goal_reached(self):
        """What the bursts must not have spoiled: the rotor manoeuvre ends at its target, the
        FreeBOT goal is ARRIVED (never ABORTED, never timed out by a stamp from the future)."""
        if self.stack == 'rotor':
            wait_until(self.goal.done, 'the manoeuvre to end', 120.0)
            time.sleep(0.5)
            x, y = _rest_position(self.last_state['odom'])
            miss = math.hypot(x - self.target[0], y - self.target[1])
            self.assertLess(miss, self.error_bound, 'the manoeuvre ended %.2e m off its target'
                            % miss)
        elif self.stack == 'freebot':
            _, verdict = self.goal.result('a final verdict')
            self.assertEqual(verdict.status, MoveFreebotResult.ARRIVED, verdict.message)


def _rest_position(odometry):
    return odometry.pose.pose.position.x, odometry.pose.pose.position.y


def _numbers(msg):
    if isinstance(msg, float):
        yield msg
    elif isinstance(msg, (list, tuple)):
        for item in msg:
            yield from _numbers(item)
    elif hasattr(msg, '__slots__'):
        for slot in msg.__slots__:
            yield from _numbers(getattr(msg, slot))


if __name__ == '__main__':
    rostest.rosrun('spherical_robots', 'hostile_input', HostileInput, sys.argv)
