#!/usr/bin/env python3
"""rostest of the hardware-interface contract (docs/hardware_interface.md): one test method per
safety behaviour, in the spirit of diff_drive_controller's rostests. It runs against
hardware_interface_sim (test/hardware_interface_sim.test) and, unchanged, against the independent
loopback driver scripts/loopback_hardware.py (test/hardware_loopback.test): any implementation of
the contract must pass it.

Runs in the node's namespace and reads the node's limits from its private parameters; ~node names
the node (relative), ~node_type its executable (for the start-up checks). Wall time, with generous timing bounds:
the checks that can be made exact (no intermediate velocities after an e-stop, acceleration between
consecutive stamps) are exact, the others allow SLACK seconds of scheduling noise.
"""
import math
import subprocess
import threading
import time
import unittest

import roslib.packages
import rospy
import rostest
from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus
from sensor_msgs.msg import JointState
from std_msgs.msg import Bool

PKG = 'spherical_robots'
NAME = 'hardware_interface_sim_check'
SLACK = 0.3          # [s] allowance for message latency and scheduling on a loaded machine
COMMAND_RATE = 20.0  # [Hz] of the test's set-point stream, well inside the watchdog timeout
EXACT = 1e-9         # [rad/s] the core reaches set-points exactly


class HardwareInterfaceSimCheck(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        node = rospy.resolve_name(rospy.get_param('~node', 'hardware_interface'))
        cls.effort_limits = rospy.get_param(node + '/effort_limits', {})
        cls.all_names = rospy.get_param(node + '/actuator_names')
        cls.names = [n for n in cls.all_names if n not in cls.effort_limits]  # velocity actuators
        cls.max_velocity = float(rospy.get_param(node + '/max_velocity', 20.0))
        cls.max_acceleration = float(rospy.get_param(node + '/max_acceleration', 50.0))
        cls.timeout = float(rospy.get_param(node + '/command_timeout', 0.5))
        cls.status_name = node.lstrip('/') + ': actuators'
        cls.lock = threading.Lock()
        cls.states = []
        cls.status = None
        cls.command_pub = rospy.Publisher('actuators/command', JointState, queue_size=10)
        cls.e_stop_pub = rospy.Publisher('estop', Bool, queue_size=10)
        rospy.Subscriber('actuators/state', JointState, cls.onState, queue_size=100)
        rospy.Subscriber('/diagnostics', DiagnosticArray, cls.onDiagnostics, queue_size=10)
        deadline = time.time() + 30.0
        while (cls.command_pub.get_num_connections() == 0
               or cls.e_stop_pub.get_num_connections() == 0
               or not cls.states or cls.status is None):
            if time.time() > deadline or rospy.is_shutdown():
                raise AssertionError('hardware_interface_sim did not come up: no connection, '
                                     'no actuators/state or no diagnostics within 30 s')
            time.sleep(0.05)

    @classmethod
    def onState(cls, msg):
        with cls.lock:
            cls.states.append(msg)

    @classmethod
    def onDiagnostics(cls, msg):
        for status in msg.status:
            if status.name == cls.status_name:
                with cls.lock:
                    cls.status = status

    # ------------------------------------------------------------------------------------------
    # helpers

    def setUp(self):
        self.resetActuators()

    def command(self, setpoints):
        """Publishes one command: setpoints maps actuator names to set-points, rates [rad/s] for
        velocity actuators, efforts for effort actuators; both arrays carry every value, and each
        actuator reads the one of its kind."""
        values = list(setpoints.values())
        self.command_pub.publish(JointState(name=list(setpoints), velocity=values, effort=values))

    def commandFor(self, velocities, duration, extra=None):
        """Streams velocities at COMMAND_RATE for duration [s]; extra (a command) is sent between
        the good ones. Returns the wall time of the last good command."""
        end = time.time() + duration
        while True:
            self.command(velocities)
            last = time.time()
            if last >= end:
                return last
            if extra is not None:
                time.sleep(0.5 / COMMAND_RATE)
                self.command(extra)
                time.sleep(0.5 / COMMAND_RATE)
            else:
                time.sleep(1.0 / COMMAND_RATE)

    def latest(self):
        with self.lock:
            return self.states[-1]

    def statesSince(self, stamp):
        with self.lock:
            return [s for s in self.states if s.header.stamp.to_sec() >= stamp]

    def velocity(self, state, name):
        return dict(zip(state.name, state.velocity))[name]

    def effort(self, state, name):
        return dict(zip(state.name, state.effort))[name]

    def waitFor(self, predicate, timeout, what):
        """Waits up to timeout [s] of wall time for predicate() to hold; fails naming what."""
        deadline = time.time() + timeout
        while not predicate():
            if time.time() > deadline:
                self.fail('timed out after %.1f s waiting for %s' % (timeout, what))
            time.sleep(0.01)

    def diagnostics(self):
        with self.lock:
            status = self.status
        return status, {kv.key: kv.value for kv in status.values}

    def rejectedCount(self):
        return int(self.diagnostics()[1]['rejected commands'])

    def resetActuators(self):
        """Releases the e-stop and brings every actuator to rest with a zero command."""
        self.e_stop_pub.publish(Bool(data=False))
        zero = {name: 0.0 for name in self.all_names}
        deadline = time.time() + 10.0
        while not all(v == 0.0 for v in self.latest().velocity + self.latest().effort):
            if time.time() > deadline:
                self.fail('the actuators did not come to rest before the test: %s'
                          % (self.latest().velocity,))
            self.command(zero)
            time.sleep(1.0 / COMMAND_RATE)

    def reach(self, velocities):
        """Streams velocities until every named actuator reports exactly its set-point."""
        ramp = max(abs(v) for v in velocities.values()) / self.max_acceleration
        deadline = time.time() + ramp + 10.0 * SLACK
        while not all(abs(self.velocity(self.latest(), n) - v) < EXACT
                      for n, v in velocities.items()):
            if time.time() > deadline:
                self.fail('set-points %s not reached within %.1f s, state %s'
                          % (velocities, ramp + 10.0 * SLACK, self.latest().velocity))
            self.command(velocities)
            time.sleep(1.0 / COMMAND_RATE)

    # ------------------------------------------------------------------------------------------
    # one test per safety behaviour

    def test_setpoints_reached_and_limited(self):
        theta, phi, psi = self.names[:3]
        start = rospy.get_time()
        within = {theta: 0.5 * self.max_velocity, phi: -0.25 * self.max_velocity}
        too_fast = {psi: 100.0}
        ramp = self.max_velocity / self.max_acceleration
        self.commandFor(dict(within, **too_fast), ramp + 1.0)
        state = self.latest()
        self.assertAlmostEqual(self.velocity(state, theta), within[theta], delta=EXACT)
        self.assertAlmostEqual(self.velocity(state, phi), within[phi], delta=EXACT)
        self.assertAlmostEqual(self.velocity(state, psi), self.max_velocity, delta=EXACT,
                               msg='100 rad/s must settle at max_velocity')
        self.waitFor(lambda: int(self.diagnostics()[1][psi + ' saturated set-points']) > 0, 5.0,
                     'diagnostics to count the clamped set-points of ' + psi)
        # Every published velocity is within the limit, and between consecutive stamps no
        # actuator changed faster than max_acceleration (stamps are the node's update times).
        states = self.statesSince(start)
        self.assertGreater(len(states), 50)
        for prev, cur in zip(states, states[1:]):
            dt = cur.header.stamp.to_sec() - prev.header.stamp.to_sec()
            self.assertGreaterEqual(dt, 0.0, 'state stamps went backwards')
            for v0, v1 in zip(prev.velocity, cur.velocity):
                self.assertLessEqual(abs(v1), self.max_velocity + EXACT)
                self.assertLessEqual(abs(v1 - v0), self.max_acceleration * dt + 1e-4,
                                     'acceleration limit exceeded: %g -> %g in %g s' % (v0, v1, dt))

    def test_reconfigured_limits_apply_mid_run(self):
        """dynamic_reconfigure lowers the rate and acceleration limits of a running actuator: its
        velocity ramps down to the new limit at the new acceleration, never jumps; a non-finite
        value is refused and the last good one is handed back and kept."""
        if not rospy.get_param('~reconfigurable', False):
            self.skipTest('this implementation offers no dynamic_reconfigure')
        from dynamic_reconfigure.client import Client
        client = Client(rospy.resolve_name(rospy.get_param('~node', 'hardware_interface')),
                        timeout=30.0)
        theta = self.names[0]
        fast = 0.75 * self.max_velocity
        lowered = {'max_velocity': 0.25 * self.max_velocity,
                   'max_acceleration': 0.5 * self.max_acceleration}
        try:
            self.reach({theta: fast})
            applied = client.update_configuration(lowered)
            for key, value in lowered.items():
                self.assertAlmostEqual(applied[key], value, delta=1e-12, msg=key)
            start = rospy.get_time()
            ramp = (fast - lowered['max_velocity']) / lowered['max_acceleration']
            self.commandFor({theta: fast}, ramp + 1.0)
            self.assertAlmostEqual(self.velocity(self.latest(), theta), lowered['max_velocity'],
                                   delta=EXACT, msg='the set-point is clamped to the new limit')
            states = self.statesSince(start)
            self.assertGreater(len(states), 20)
            for prev, cur in zip(states, states[1:]):
                dt = cur.header.stamp.to_sec() - prev.header.stamp.to_sec()
                v0, v1 = self.velocity(prev, theta), self.velocity(cur, theta)
                self.assertLessEqual(abs(v1 - v0), lowered['max_acceleration'] * dt + 1e-4,
                                     'faster than the new acceleration limit: %g -> %g in %g s'
                                     % (v0, v1, dt))

            kept = client.update_configuration({'command_timeout': float('nan')})
            self.assertAlmostEqual(kept['command_timeout'], self.timeout, delta=1e-12)
            self.waitFor(lambda: 'command_timeout' in
                         self.diagnostics()[1]['last refused reconfiguration'], 5.0,
                         'diagnostics to name the refused command_timeout')
        finally:
            client.update_configuration({'max_velocity': self.max_velocity,
                                         'max_acceleration': self.max_acceleration,
                                         'command_timeout': self.timeout})

    def test_watchdog_brings_actuators_to_rest(self):
        theta = self.names[0]
        v = 0.5 * self.max_velocity
        self.reach({theta: v})
        last_command = self.commandFor({theta: v}, 0.5)
        # Position when the last command left, from the newest state no later than that.
        before = [s for s in self.statesSince(0.0) if s.header.stamp.to_sec() <= last_command]
        position = dict(zip(before[-1].name, before[-1].position))[theta]
        stop_time = self.timeout + v / self.max_acceleration
        self.waitFor(lambda: self.velocity(self.latest(), theta) == 0.0,
                     stop_time + 10.0 * SLACK, 'the watchdog to stop %s' % theta)
        at_rest = next(s for s in self.statesSince(last_command) if self.velocity(s, theta) == 0.0)
        elapsed = at_rest.header.stamp.to_sec() - last_command
        self.assertLessEqual(elapsed, stop_time + SLACK,
                             'at rest %.3f s after the last command; closed form %.3f s'
                             % (elapsed, stop_time))
        self.assertGreaterEqual(elapsed, self.timeout - 0.05, 'watchdog fired early')
        # Travel after the last command: v for the timeout (plus latency), then the ramp down
        # v^2/(2a): with v = 2 rad/s, a = 8 rad/s^2, 0.5 s timeout that is 1.25 rad.
        travel = dict(zip(at_rest.name, at_rest.position))[theta] - position
        bound = v * (self.timeout + SLACK) + v * v / (2.0 * self.max_acceleration)
        self.assertLess(travel, bound, 'travelled %.3f rad after the last command' % travel)
        self.assertGreater(travel, v * (self.timeout - 0.1), 'travelled only %.3f rad' % travel)
        self.waitFor(lambda: self.diagnostics()[0].level == DiagnosticStatus.WARN and
                     'command timeout' in self.diagnostics()[0].message,
                     5.0, 'diagnostics to report the command timeout')

    def test_nan_command_ignored(self):
        theta, phi = self.names[:2]
        v = 0.25 * self.max_velocity
        self.reach({theta: v})
        rejected = self.rejectedCount()
        start = rospy.get_time()
        bad = {theta: float('nan'), phi: -v}
        self.commandFor({theta: v}, 1.0, extra=bad)
        for state in self.statesSince(start):
            self.assertTrue(all(math.isfinite(x) for x in state.velocity + state.position),
                            'a non-finite value reached actuators/state: %s' % (state,))
            self.assertAlmostEqual(self.velocity(state, theta), v, delta=EXACT)
            self.assertEqual(self.velocity(state, phi), 0.0, 'a rejected command changed phi')
        # Node alive: states keep coming; diagnostics count the rejections and say why.
        now = rospy.get_time()
        self.waitFor(lambda: self.latest().header.stamp.to_sec() > now, 2.0, 'a fresh state')
        self.waitFor(lambda: self.rejectedCount() >= rejected + 10, 5.0,
                     'diagnostics to count the NaN commands')
        self.assertIn('non-finite', self.diagnostics()[1]['last rejection'])

    def test_implausible_set_point_rejected_not_clamped(self):
        """A set-point beyond 100 times its limit (1e300) is rejected as a whole; 100 times is
        clamped."""
        theta, phi = self.names[:2]
        v = 0.25 * self.max_velocity
        self.reach({theta: v})
        start = rospy.get_time()
        self.commandFor({theta: v}, 1.0, extra={theta: 1e300, phi: -v})
        for state in self.statesSince(start):
            self.assertAlmostEqual(self.velocity(state, theta), v, delta=EXACT,
                                   msg='an implausible command moved theta')
            self.assertEqual(self.velocity(state, phi), 0.0, 'a rejected command changed phi')
        self.waitFor(lambda: 'beyond 100 times its limit' in self.diagnostics()[1]['last rejection'],
                     5.0, 'diagnostics to name the implausible set-point')
        key = theta + ' set-point, velocity [rad/s]'
        self.commandFor({theta: -100.0 * self.max_velocity}, 0.3)
        self.waitFor(lambda: float(self.diagnostics()[1][key].split(',')[0]) == -self.max_velocity,
                     5.0, '-100 times the limit clamped to -max_velocity')

    def test_rejection_burst_escalates_diagnostics_and_recovers(self):
        """More than 20 rejected commands a second: ERROR naming the reason; 2 s of good
        commands after the burst: OK again."""
        theta = self.names[0]
        self.reach({theta: 0.1 * self.max_velocity})
        good, bad = {theta: 0.1 * self.max_velocity}, {theta: float('nan')}
        seen = None  # the first ERROR status the burst brings
        for k in range(int(2.5 * 100)):  # 100 commands a second, four in five of them NaN
            self.command(good if k % 5 == 0 else bad)
            status, values = self.diagnostics()
            if seen is None and status.level == DiagnosticStatus.ERROR:
                seen = status, values
            time.sleep(0.01)
        self.assertIsNotNone(seen, 'no ERROR on /diagnostics during 2.5 s of 80 NaN commands a '
                             'second; last: %s' % self.diagnostics()[0].message)
        status, values = seen
        self.assertIn('bad messages on', status.message)
        self.assertIn('non-finite', status.message)
        self.assertGreater(float(values[rospy.resolve_name('actuators/command')
                                        + ' rejected per second']), 20.0)
        self.commandFor({theta: 0.1 * self.max_velocity}, 3.5)
        self.waitFor(lambda: self.diagnostics()[0].level == DiagnosticStatus.OK, 5.0,
                     'diagnostics back at OK after 2 s of good commands')

    def test_unknown_joint_rejected(self):
        theta = self.names[0]
        v = 0.25 * self.max_velocity
        self.reach({theta: v})
        rejected = self.rejectedCount()
        start = rospy.get_time()
        self.commandFor({theta: v}, 1.0, extra={theta: -v, 'no_such_joint': 1.0})
        for state in self.statesSince(start):
            self.assertAlmostEqual(self.velocity(state, theta), v, delta=EXACT,
                                   msg='a command naming an unknown joint was applied')
            self.assertNotIn('no_such_joint', state.name)
        self.waitFor(lambda: self.rejectedCount() >= rejected + 10, 5.0,
                     'diagnostics to count the unknown-joint commands')
        self.assertIn("unknown actuator 'no_such_joint'", self.diagnostics()[1]['last rejection'])

    def test_e_stop_zeroes_and_rejects_until_released(self):
        v = 0.9 * self.max_velocity
        moving = {name: v for name in self.names}
        self.reach(moving)
        engaged = rospy.get_time()
        self.e_stop_pub.publish(Bool(data=True))
        # Commands keep coming while engaged; they must all be rejected.
        self.commandFor(moving, 1.0)
        after = self.statesSince(engaged)
        for state in after:
            for x in state.velocity:
                self.assertTrue(x == 0.0 or abs(x - v) < EXACT,
                                'e-stop must zero at once, not ramp: saw %g' % x)
        self.assertTrue(all(x == 0.0 for x in self.latest().velocity),
                        'still moving 1 s after the e-stop: %s' % (self.latest().velocity,))
        stopped = next(s for s in after if all(x == 0.0 for x in s.velocity))
        self.assertLess(stopped.header.stamp.to_sec() - engaged, SLACK)
        self.waitFor(lambda: self.diagnostics()[0].level == DiagnosticStatus.ERROR, 5.0,
                     'diagnostics to report the e-stop')
        status, values = self.diagnostics()
        self.assertIn('e-stop engaged', status.message)
        self.assertIn('e-stop', values['last rejection'])

        self.e_stop_pub.publish(Bool(data=False))
        self.reach(moving)

    def effortActuator(self):
        if not self.effort_limits:
            self.skipTest('the node under test has no effort actuators (~effort_limits)')
        name = sorted(self.effort_limits)[0]
        return name, float(self.effort_limits[name])

    def test_effort_setpoints_applied_and_limited(self):
        name, limit = self.effortActuator()
        self.commandFor({name: 0.5 * limit}, 0.5)
        state = self.latest()
        self.assertEqual(self.effort(state, name), 0.5 * limit, 'an ideal effort actuator '
                         'applies its set-point at once')
        self.assertEqual(self.velocity(state, name), 0.0)
        self.commandFor({name: -10.0 * limit}, 0.5)
        self.assertEqual(self.effort(self.latest(), name), -limit, 'not clamped to the limit')
        # The velocity actuators report no effort.
        for other in self.names:
            self.assertEqual(self.effort(self.latest(), other), 0.0)

    def test_effort_dropped_by_watchdog_and_e_stop(self):
        name, limit = self.effortActuator()
        last_command = self.commandFor({name: limit}, 0.5)
        self.waitFor(lambda: self.effort(self.latest(), name) == 0.0, self.timeout + 10.0 * SLACK,
                     'the watchdog to drop the effort')
        dropped = next(s for s in self.statesSince(last_command) if self.effort(s, name) == 0.0)
        self.assertLessEqual(dropped.header.stamp.to_sec() - last_command, self.timeout + SLACK)
        self.assertGreaterEqual(dropped.header.stamp.to_sec() - last_command, self.timeout - 0.05)

        self.commandFor({name: limit}, 0.3)
        engaged = rospy.get_time()
        self.e_stop_pub.publish(Bool(data=True))
        self.commandFor({name: limit}, 0.5)
        stopped = next(s for s in self.statesSince(engaged) if self.effort(s, name) == 0.0)
        self.assertLess(stopped.header.stamp.to_sec() - engaged, SLACK)
        self.assertEqual(self.effort(self.latest(), name), 0.0, 'effort applied during the e-stop')
        self.e_stop_pub.publish(Bool(data=False))

    def test_malformed_parameters_fail_at_startup(self):
        node_type = rospy.get_param('~node_type', 'hardware_interface_sim')
        node = roslib.packages.find_node(PKG, node_type)
        self.assertTrue(node, node_type + ' not found')
        base = {'actuator_names': ['theta', 'phi'], 'max_velocity': 5.0}
        cases = [
            ('missing_names', {'max_velocity': 5.0}, 'actuator_names'),
            ('names_not_a_list', dict(base, actuator_names='theta'), 'actuator_names'),
            ('duplicate_names', dict(base, actuator_names=['theta', 'theta']), 'actuator_names'),
            ('negative_velocity', dict(base, max_velocity=-1.0), 'max_velocity'),
            ('zero_acceleration', dict(base, max_acceleration=0), 'max_acceleration'),
            ('nan_timeout', dict(base, command_timeout=float('nan')), 'command_timeout'),
            ('text_rate', dict(base, rate='fast'), 'rate'),
            ('unknown_effort_actuator', dict(base, effort_limits={'slider': 5.0}), 'effort_limits'),
            ('negative_effort_limit', dict(base, effort_limits={'phi': -1.0}), 'effort_limits'),
        ]
        for case, params, bad in cases:
            name = 'bad_' + case
            for key, value in params.items():
                rospy.set_param(name + '/' + key, value)
            try:
                result = subprocess.run([node[0], '__name:=' + name], capture_output=True,
                                        text=True, timeout=30)
            finally:
                rospy.delete_param(name)
            self.assertNotEqual(result.returncode, 0, '%s: the node started' % case)
            output = result.stdout + result.stderr
            self.assertIn('FATAL', output, case)
            # The message names the node's namespace and the bad parameter.
            self.assertIn(rospy.resolve_name(name), output, case)
            self.assertIn(bad, output, case)


if __name__ == '__main__':
    rospy.init_node(NAME)
    rostest.rosrun(PKG, NAME, HardwareInterfaceSimCheck)
