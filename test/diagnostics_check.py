#!/usr/bin/env python3
"""rostest of a stack's diagnostics (test/diagnostics_*.test), in the stack's namespace.

~groups: the aggregator's groups ({group: level name}) the stack's diagnostics_agg must reach,
e.g. {plant: OK, controller: OK, hardware: OK}, or with hardware:=none {hardware: STALE}.
~silence: a node of the stack (relative name) stopped (SIGSTOP; continued at the end) once one of
its rates was measured OK: it goes silent without dying, which would end the stack
(respawn:=false) or restart the node (true).
~rates: the topics whose rate statuses are checked ([] none); each is counted here, by the
header stamps of its messages, over the window the status says it measured, and the rate the
status reports must be that count's (an independent truth), within the configured tolerance of
its target, at OK.
"""
import functools
import os
import signal
import unittest

import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState

from spherical_robots.msg import TerrainState
import spherical_robots_testing as testing

PKG = 'spherical_robots'
NAME = 'diagnostics_check'
WALL_DEADLINE = 120.0
LEVELS = {'OK': DiagnosticStatus.OK, 'WARN': DiagnosticStatus.WARN,
          'ERROR': DiagnosticStatus.ERROR, 'STALE': DiagnosticStatus.STALE}
TYPES = {'terrain_state': TerrainState, 'odom': Odometry, 'actuators/command': JointState,
         'actuators/state': JointState}
# An event stamped at the window's start or at its end may fall either side of it in seconds.
EDGE_EVENTS = 2

wait_until = functools.partial(testing.wait_until, timeout=WALL_DEADLINE)


def value(status, key):
    return next((kv.value for kv in status.values if kv.key == key), None)


def stamps_between(recorder, start, end):
    """How many of the recorded messages are stamped in (start, end] [s]."""
    return sum(1 for msg in recorder.since(0) if start < msg.header.stamp.to_sec() <= end)


class DiagnosticsCheck(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node(NAME)
        cls.groups = rospy.get_param('~groups')
        cls.rates = rospy.get_param('~rates', [])
        cls.counters = {topic: testing.Recorder(rospy.resolve_name(topic), TYPES[topic])
                        for topic in cls.rates}
        cls.aggregated = testing.Recorder('diagnostics_agg', DiagnosticArray)
        cls.raw = testing.Recorder('/diagnostics', DiagnosticArray)
        cls.silenced_pid = None
        victim = rospy.get_param('~silence', '')
        if victim:
            node = rospy.resolve_name(victim)
            status = node.lstrip('/') + ':'
            # Once the loop runs: a rate measured at OK.
            wait_until(lambda: any(s.name.startswith(status) and s.level == DiagnosticStatus.OK
                                   and value(s, 'Actual frequency (Hz)')
                                   for msg in cls.raw.since(0) for s in msg.status),
                       'a rate of ' + node + ' measured at OK')
            rospy.loginfo('silencing %s', node)
            cls.silenced_pid = testing.pid_of(node)
            os.kill(cls.silenced_pid, signal.SIGSTOP)

    @classmethod
    def tearDownClass(cls):
        if cls.silenced_pid is not None:
            os.kill(cls.silenced_pid, signal.SIGCONT)

    def latest_groups(self):
        msg = self.aggregated.last()
        if msg is None:
            return {}
        return {s.name.strip('/'): s for s in msg.status if s.name.count('/') == 1}

    def latest_items(self):
        """Every status of the latest aggregated array, for a failure's message."""
        msg = self.aggregated.last()
        return [(s.name, s.level, s.message) for s in msg.status] if msg else []

    def test_groups(self):
        wanted = {group: LEVELS[level] for group, level in self.groups.items()}
        seen = {}

        def reached():
            seen.clear()
            seen.update({g: (s.level, s.message) for g, s in self.latest_groups().items()})
            return all(g in seen and seen[g][0] == level for g, level in wanted.items())

        try:
            wait_until(reached, 'groups %s on %s' % (self.groups, rospy.resolve_name(
                'diagnostics_agg')))
        except AssertionError as e:
            raise AssertionError('%s; last seen: %s' % (e, self.latest_items()))
        self.assertNotIn('Other', self.latest_groups(),
                         'statuses of this stack outside every group')

    def rate_status(self, topic):
        name = ': ' + rospy.resolve_name(topic).lstrip('/') + ' rate'
        for msg in reversed(self.raw.since(0)):
            for status in msg.status:
                if status.name.endswith(name) and value(status, 'Actual frequency (Hz)'):
                    return status
        return None

    def test_rates(self):
        for topic in self.rates:
            # A full window (5 reports) after time started.
            wait_until(lambda: self.rate_status(topic) is not None and
                       int(value(self.rate_status(topic), 'Events since startup')) >
                       int(value(self.rate_status(topic), 'Events in window')),
                       'a full window of the rate of ' + topic)
            status = self.rate_status(topic)
            window = float(value(status, 'Duration of window (s)'))
            end = float(value(status, 'End of window (s)'))
            reported = float(value(status, 'Actual frequency (Hz)'))
            target = float(value(status, 'Target frequency (Hz)'))
            lowest = float(value(status, 'Minimum acceptable frequency (Hz)'))
            # The topic and /diagnostics come over different connections: under load the
            # window's last messages may still be on their way when its status is read.
            wait_until(lambda: any(msg.header.stamp.to_sec() > end
                                   for msg in self.counters[topic].since(0)),
                       'a message of %s stamped after the window' % topic)
            counted = stamps_between(self.counters[topic], end - window, end)
            rospy.loginfo('%s: reported %.3f Hz over %.2f s of ROS time, counted %d messages '
                          '(%.3f Hz), target %.3f Hz', topic, reported, window, counted,
                          counted / window, target)
            self.assertGreater(window, 1.0)
            self.assertLessEqual(abs(reported * window - counted), EDGE_EVENTS, status)
            self.assertGreaterEqual(counted / window, lowest, status)
            self.assertLessEqual(counted / window, target + (target - lowest), status)
            self.assertEqual(status.level, DiagnosticStatus.OK, status)


if __name__ == '__main__':
    rostest.rosrun(PKG, NAME, DiagnosticsCheck)
