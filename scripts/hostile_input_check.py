#!/usr/bin/env python3
"""Hostile input against a running stack, from a table of cases (rostest).

For every subscribed topic of the stack's loop it sends bursts of bad messages -- NaN, +-Inf,
+-1e300, empty and mis-sized arrays, unknown and duplicated names, zero and non-unit vectors,
stamps at 0, in the past and in the future -- and one stray /clock 1,000 s ahead. After each
burst: no node of the stack has died, no message the stack published (on any topic of its
namespace, /tf) holds a non-finite number, and the stack tracks again within `~recovery` [s] of
simulated time (the tracking error below `~error_bound`). During a burst into the hardware
interface its /diagnostics must leave OK (it escalates on rejections), and return to OK after it.

Private parameters: ~stack (terrain | norma), ~error_bound [m], ~recovery [s] of simulated time
(2), ~burst [s] of wall time per case (0.2, at ~500 messages per second), ~nodes (the node names
that must survive). Run in the stack's namespace.
"""
import copy
import math
import sys
import threading
import time
import unittest

import rosgraph
import rosnode
import rospy
import rostest
import rostopic
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import JointState

from spherical_robots.msg import NormaState, TerrainState, TrackingError
from spherical_robots_testing import wait_until

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


def terrain_state_cases(last):
    cases = []
    for label, edit in (('contact NaN', lambda m: setattr(m.contact_point, 'x', NAN)),
                        ('contact 1e300', lambda m: setattr(m.contact_point, 'y', HUGE)),
                        ('centre -Inf', lambda m: setattr(m.centre, 'z', -INF)),
                        ('zero normal', lambda m: setattr(m.normal, 'z', 0.0)),
                        ('non-unit heading', lambda m: setattr(m.heading, 'x', 3.0)),
                        ('phi 1e300', lambda m: setattr(m, 'phi', HUGE))):
        msg = copy.deepcopy(last)
        msg.header.stamp = rospy.Time.now()
        edit(msg)
        cases.append((label, msg))
    return cases + stamped_copies(last, 'terrain_state')


def norma_state_cases(last):
    cases = []
    for label, edit in (('q NaN', lambda m: m.q.__setitem__(1, NAN)),
                        ('x 1e300', lambda m: setattr(m, 'x', HUGE)),
                        ('qd -Inf', lambda m: m.qd.__setitem__(0, -INF)),
                        ('delta -1e300', lambda m: m.q.__setitem__(3, -HUGE))):
        msg = copy.deepcopy(last)
        msg.q = list(msg.q)
        msg.qd = list(msg.qd)
        msg.header.stamp = rospy.Time.now()
        edit(msg)
        cases.append((label, msg))
    return cases + stamped_copies(last, 'norma_state')


# Per stack: (topic, type, case maker given the last message seen on it) of what it subscribes,
# the actuator names and value field, the published topics to watch, and the hardware's status.
STACKS = {
    'terrain': {
        'actuators': (['theta', 'phi', 'psi'], 'velocity'),
        'states': [('terrain_state', TerrainState, terrain_state_cases)],
    },
    'norma': {
        'actuators': (['pendulum_motor', 'slider_motor'], 'effort'),
        'states': [('norma_state', NormaState, norma_state_cases)],
    },
}


class HostileInput(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        rospy.init_node('hostile_input_check')
        cls.stack = rospy.get_param('~stack')
        cls.spec = STACKS[cls.stack]
        cls.error_bound = float(rospy.get_param('~error_bound'))
        cls.recovery = float(rospy.get_param('~recovery', 2.0))
        cls.burst = float(rospy.get_param('~burst', 0.2))
        cls.nodes = [rospy.resolve_name(n) for n in rospy.get_param('~nodes')]
        cls.lock = threading.Lock()
        cls.non_finite = []  # (topic, field)
        cls.errors = []      # (simulated time, |e|)
        cls.hardware_levels = []  # (wall time, level) of the hardware interface's status
        cls.last_hardware_status = None
        rospy.Subscriber('tracking_error', TrackingError, cls.on_error, queue_size=100)
        rospy.Subscriber('/diagnostics', DiagnosticArray, cls.on_diagnostics, queue_size=100)
        cls.last_state = {}
        for topic, msg_type, _ in cls.spec['states']:
            rospy.Subscriber(topic, msg_type, cls.on_state, callback_args=topic, queue_size=10)
        cls.watched = set()
        cls.watch_timer = rospy.Timer(rospy.Duration(0.5), cls.watch_new_topics)
        wait_until(lambda: len(cls.watched) > 3, 'the stack to publish', 60.0)

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
        with cls.lock:
            cls.errors.append((rospy.get_time(), msg.error_norm))

    @classmethod
    def on_state(cls, msg, topic):
        # Our own hostile copies arrive here too: only the stack's (finite, plausible) ones count.
        if non_finite_field(msg) is None and msg.header.stamp.to_sec() > 0.0 \
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

    def burst_of(self, publisher, messages):
        """Publishes the messages round-robin at RATE for self.burst seconds of wall time."""
        end = time.time() + self.burst
        k = 0
        while time.time() < end:
            publisher.publish(messages[k % len(messages)])
            k += 1
            time.sleep(1.0 / RATE)
        return k

    def assert_tracks_again(self, what):
        """The tracking error is below the bound within self.recovery s of simulated time."""
        start = rospy.get_time()
        def recovered():
            with self.lock:
                return any(t >= start and e < self.error_bound for t, e in self.errors)
        wait_until(lambda: recovered() or rospy.get_time() > start + self.recovery,
                   'tracking after %s' % what, 60.0)
        with self.lock:
            after = [e for t, e in self.errors if t >= start]
        self.assertTrue(recovered(), 'after %s the stack does not track within %.1f s of simulated '
                        'time: |e| %s (bound %g m)' % (what, self.recovery,
                                                       after[-5:], self.error_bound))

    def assert_nothing_died_or_went_non_finite(self, what):
        for node in self.nodes:
            self.assertTrue(rosnode.rosnode_ping(node, max_count=1), '%s died after %s'
                            % (node, what))
        with self.lock:
            self.assertEqual(self.non_finite, [], 'non-finite numbers published after %s: %s'
                             % (what, self.non_finite[:5]))

    def wait_for_tracking(self):
        wait_until(lambda: self.errors and self.errors[-1][1] < self.error_bound,
                   'the stack to track within %g m' % self.error_bound, 120.0)

    # --- the cases ------------------------------------------------------------------------------

    def test_1_actuator_inputs(self):
        """Bad actuator states into the plant and bad commands into the hardware interface."""
        self.wait_for_tracking()
        names, field = self.spec['actuators']
        for topic in ('actuators/state', 'actuators/command'):
            publisher = rospy.Publisher(topic, JointState, queue_size=1000)
            wait_until(lambda: publisher.get_num_connections() > 1, 'subscribers of ' + topic, 20.0)
            for label, msg in joint_state_cases(names, field):
                what = '%s on %s' % (label, topic)
                sent = self.burst_of(publisher, [msg])
                rospy.loginfo('%s: %d messages', what, sent)
                self.assert_nothing_died_or_went_non_finite(what)
                self.assert_tracks_again(what)
            publisher.unregister()

    def test_2_state_inputs(self):
        """Bad state messages into the controller; then the stamped copies of a good one."""
        self.wait_for_tracking()
        for topic, msg_type, cases in self.spec['states']:
            wait_until(lambda: topic in self.last_state, 'a state on ' + topic, 20.0)
            publisher = rospy.Publisher(topic, msg_type, queue_size=1000)
            wait_until(lambda: publisher.get_num_connections() > 1, 'subscribers of ' + topic, 20.0)
            for label, msg in cases(self.last_state[topic]):
                sent = self.burst_of(publisher, [msg])
                rospy.loginfo('%s: %d messages', label, sent)
                self.assert_nothing_died_or_went_non_finite(label)
                self.assert_tracks_again(label)
            publisher.unregister()

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
        names, field = self.spec['actuators']
        publisher = rospy.Publisher('actuators/command', JointState, queue_size=1000)
        wait_until(lambda: publisher.get_num_connections() > 1, 'the hardware interface', 20.0)
        start = time.time()
        bad = joint_state_cases(names, field)[0][1]
        end = start + 3.0  # long enough for two of the updater's 1 s reports
        while time.time() < end:
            publisher.publish(bad)
            time.sleep(1.0 / RATE)
        with self.lock:
            during = [level for t, level in self.hardware_levels if t > start + 0.5]
        self.assertIn(DiagnosticStatus.ERROR, during,
                      'the hardware status did not reach ERROR under %.0f rejected commands/s: %s'
                      % (RATE, during))
        ok_again = time.time()
        try:
            wait_until(lambda: any(t > ok_again and level == DiagnosticStatus.OK
                                   for t, level in list(self.hardware_levels)),
                       'the hardware status back at OK after the burst', 20.0)
        except AssertionError as e:
            with self.lock:
                raise AssertionError('%s; levels since: %s; last: %s' % (
                    e, [level for t, level in self.hardware_levels if t > ok_again],
                    self.last_hardware_status))


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
