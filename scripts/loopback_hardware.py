#!/usr/bin/env python3
"""A second, independent implementation of the hardware-interface contract
(docs/hardware_interface.md), written from the document alone and sharing no code with
hardware_interface_sim: rate set-points on `actuators/command` are followed by ideal actuators
(velocity and acceleration limits, nothing else), effort set-points are applied at once within
their limits, and both are looped back as measured states on `actuators/state`, with the command-timeout watchdog, the latched `estop` and the rejection
rules of the contract. It is what a minimal real driver looks like, and the stacks' rostests run
with it in place of hardware_interface_sim (`hardware:=loopback`) to show that nothing else
depends on the simulated one.

Private parameters, as hardware_interface_sim's: actuator_names (required), max_velocity [rad/s],
max_acceleration [rad/s^2], effort_limits ({name: max effort}: those actuators take efforts),
command_timeout [s], rate [Hz], diagnostic_period [s], max_clock_step [s]; models_file
must be empty (there are no actuator models here). A missing or
malformed one is fatal at start-up (exit status 1, the message naming node and parameter).

Listed in <ns>/lockstep/participants it takes part in lock-step time as docs/lockstep.md says,
written from that text: it updates and publishes when asked on ~lockstep/step, not on a timer.
"""
import collections
import math
import os
import sys
import threading
import time

import diagnostic_updater
import rospy
from diagnostic_msgs.msg import DiagnosticStatus
from sensor_msgs.msg import JointState
from std_msgs.msg import Bool

from spherical_robots.msg import LockstepAck, LockstepStep


IMPLAUSIBLE_FACTOR = 100.0  # a set-point beyond this many times its limit is rejected


class ParameterError(Exception):
    pass


def positive_parameter(name, default):
    value = rospy.get_param('~' + name, default)
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ParameterError('parameter %s: %r is not a number' % (rospy.resolve_name('~' + name),
                                                                   value))
    if not math.isfinite(value) or value <= 0.0:
        raise ParameterError('parameter %s: %r must be finite and > 0'
                             % (rospy.resolve_name('~' + name), value))
    return float(value)


def effort_limits(names):
    key = rospy.resolve_name('~effort_limits')
    limits = rospy.get_param(key, {})
    if not isinstance(limits, dict):
        raise ParameterError('parameter %s: %r is not a dictionary name -> max effort'
                             % (key, limits))
    for name, limit in limits.items():
        if name not in names:
            raise ParameterError('parameter %s/%s names no actuator in actuator_names'
                                 % (key, name))
        if isinstance(limit, bool) or not isinstance(limit, (int, float)) \
                or not math.isfinite(limit) or limit <= 0.0:
            raise ParameterError('parameter %s/%s: %r must be finite and > 0' % (key, name, limit))
    return {name: float(limit) for name, limit in limits.items()}


def actuator_names():
    key = rospy.resolve_name('~actuator_names')
    if not rospy.has_param(key):
        raise ParameterError('parameter %s is required (a list of actuator names)' % key)
    names = rospy.get_param(key)
    if (not isinstance(names, list) or not names
            or not all(isinstance(n, str) and n for n in names)):
        raise ParameterError('parameter %s: %r is not a non-empty list of names' % (key, names))
    if len(set(names)) != len(names):
        raise ParameterError('parameter %s: %r names an actuator twice' % (key, names))
    return names


class LoopbackHardware:

    def __init__(self):
        self.names = actuator_names()
        self.max_velocity = positive_parameter('max_velocity', 20.0)
        self.max_acceleration = positive_parameter('max_acceleration', 50.0)
        self.effort_limits = effort_limits(self.names)
        self.timeout = positive_parameter('command_timeout', 0.5)
        self.max_clock_step = positive_parameter('max_clock_step', 5.0)
        rate = positive_parameter('rate', 100.0)
        models_file = rospy.get_param('~models_file', '')
        if models_file:
            raise ParameterError('parameter %s: %r: the loopback driver has ideal actuators and '
                                 'no models; use hardware:=sim for actuator models'
                                 % (rospy.resolve_name('~models_file'), models_file))

        count = len(self.names)
        self.lock = threading.Lock()
        self.setpoints = [0.0] * count
        self.velocities = [0.0] * count
        self.positions = [0.0] * count
        self.efforts = [0.0] * count
        self.saturations = [0] * count
        self.last_update = None
        self.last_accepted = None  # ROS time of the last accepted command
        self.timed_out = False
        self.e_stopped = False
        self.accepted = 0
        self.rejected = 0
        self.last_rejection = 'none'
        self.clock_jumps = 0
        self.rejection_times = collections.deque()  # wall times of the last second's rejections
        self.last_rejection_wall = None
        self.accepted_since_rejection = False

        self.updater = diagnostic_updater.Updater()
        self.updater.setHardwareID('loopback')
        self.updater.add('actuators', self.diagnose)
        self.state_pub = rospy.Publisher('actuators/state', JointState, queue_size=10)
        self.command_sub = rospy.Subscriber('actuators/command', JointState, self.on_command,
                                            queue_size=10)
        rospy.Subscriber('estop', Bool, self.on_e_stop, queue_size=10)
        self.period = 1.0 / rate
        participants = rospy.get_param('lockstep/participants', [])
        self.lockstep = rospy.get_name() in [rospy.names.ns_join(rospy.get_namespace(), name)
                                             for name in participants]
        if self.lockstep:
            self.command_topic = rospy.resolve_name('actuators/command')
            self.received = {}     # (topic, publisher's caller id) -> latest stamp received [ns]
            self.expected = {}     # topic -> (stamp [ns], publisher or '') the pending request waits for
            self.pending = None    # the stamp of the request not yet worked
            self.step_time = None  # [s] the latest step worked at
            self.last_request_wall = None
            self.loop_cpu = -1     # the CPU this process was moved to (-1: none)
            self.ack_pub = rospy.Publisher('lockstep/ack', LockstepAck, queue_size=100,
                                           tcp_nodelay=True)
            rospy.Subscriber('~lockstep/step', LockstepStep, self.on_step, queue_size=100,
                             tcp_nodelay=True)
            threading.Thread(target=self.send_joins, daemon=True).start()
        else:
            self.timer = rospy.Timer(rospy.Duration(self.period), self.on_timer)

    def send_joins(self):
        """Asks to join every 0.25 s of wall time until a request comes, and again after 1 s
        without one (docs/lockstep.md, "Joining")."""
        connected_since = None  # its subscription's publisher may not send to it at once
        while not rospy.is_shutdown():
            time.sleep(0.25)
            with self.lock:
                quiet = (self.last_request_wall is None
                         or time.time() - self.last_request_wall > 1.0)
            if self.command_sub.get_num_connections() == 0:
                connected_since = None
            elif connected_since is None:
                connected_since = time.time()
            if quiet and connected_since is not None and time.time() - connected_since >= 1.0:
                self.ack_pub.publish(LockstepAck(participant=rospy.get_name()))

    def on_step(self, request):
        if request.participant != rospy.get_name():
            return
        self.follow_loop_cpu(request.cpu)
        with self.lock:
            self.last_request_wall = time.time()
            publishers = (request.input_publishers
                          if len(request.input_publishers) == len(request.inputs)
                          else [''] * len(request.inputs))
            self.expected = {topic: (stamp.to_nsec(), publisher) for topic, stamp, publisher
                             in zip(request.inputs, request.input_stamps, publishers)
                             if topic == self.command_topic}
            self.pending = request.stamp
            self.work_if_ready()
        self.updater.update()

    def follow_loop_cpu(self, cpu):
        """Every thread of this process onto the loop's CPU, once per CPU a request names; -1
        names none (docs/lockstep.md, "One CPU for the loop")."""
        if cpu < 0 or cpu == self.loop_cpu:
            return
        self.loop_cpu = cpu
        for tid in os.listdir('/proc/self/task'):
            try:
                os.sched_setaffinity(int(tid), {cpu})
            except ProcessLookupError:  # ended since the listing
                pass
            except OSError as error:
                rospy.logwarn('%s stays where it is: moving to CPU %d failed: %s'
                              % (rospy.get_name(), cpu, error))
                return
        rospy.loginfo("%s runs on CPU %d, the lock-step loop's", rospy.get_name(), cpu)

    def arrived(self, topic, stamp, publisher):
        """A message on topic at least stamp [ns] recent came from publisher (any if '')."""
        return any(latest >= stamp for (received_topic, sender), latest in self.received.items()
                   if received_topic == topic and publisher in ('', sender))

    def work_if_ready(self):
        """With the lock held: the pending step's work once its inputs are in."""
        if self.pending is None or not all(self.arrived(topic, stamp, publisher)
                                           for topic, (stamp, publisher) in self.expected.items()):
            return
        stamp, self.pending = self.pending, None
        self.step_time = stamp.to_sec()
        self.advance(self.step_time)
        self.publish(self.step_time, stamp)  # the exact stamp: a float round trip is 1 ns off
        self.ack_pub.publish(LockstepAck(stamp=stamp, participant=rospy.get_name(),
                                         published=[self.state_pub.resolved_name],
                                         next=stamp + rospy.Duration(self.period)))

    def command_time(self, msg):
        """ROS time; in lock-step the command's stamp if it is within a second ahead of the
        latest step (the controller stamps its commands with their step), else that step."""
        if not self.lockstep:
            return rospy.get_time()
        step = self.step_time if self.step_time is not None else 0.0
        stamp = msg.header.stamp.to_sec()
        return stamp if step < stamp <= step + 1.0 else step

    def advance(self, now):
        """Moves every velocity towards its set-point at max_acceleration and integrates the
        positions (trapezoid) up to now; the watchdog zeroes the set-points at its deadline."""
        if self.last_update is None:
            self.last_update = now
            return
        if now < self.last_update or now - self.last_update > self.max_clock_step:
            # A jump of ROS time, not elapsed time: continue from `now`, the command's age kept.
            if self.last_accepted is not None:
                self.last_accepted += now - self.last_update
            rospy.logwarn('loopback hardware: ROS time jumped from %.3f to %.3f s',
                          self.last_update, now)
            self.clock_jumps += 1
            self.last_update = now
            return
        if (self.last_accepted is not None and not self.timed_out
                and now - self.last_accepted > self.timeout):
            self.setpoints = [0.0] * len(self.names)
            self.efforts = [0.0] * len(self.names)
            self.timed_out = True
            rospy.logwarn('loopback hardware: no command for %g s: actuators brought to rest',
                          self.timeout)
        dt = max(0.0, now - self.last_update)
        step = self.max_acceleration * dt
        for i, target in enumerate(self.setpoints):
            if self.names[i] in self.effort_limits:
                self.efforts[i] = target
                continue
            before = self.velocities[i]
            after = before + max(-step, min(step, target - before))
            self.positions[i] += 0.5 * (before + after) * dt
            self.velocities[i] = after
        self.last_update = now

    def rejection(self, msg):
        if self.e_stopped:
            return 'e-stop engaged: commands are rejected until it is released'
        if not msg.name:
            return 'command names no actuator'
        if len(set(msg.name)) != len(msg.name):
            return 'an actuator is named twice in one command'
        for k, name in enumerate(msg.name):
            if name not in self.names:
                return "unknown actuator '%s' (known: %s)" % (name, ', '.join(self.names))
            kind, values = (('effort', msg.effort) if name in self.effort_limits
                            else ('velocity', msg.velocity))
            if k >= len(values):
                return 'command has %d names but %d %s' % (
                    len(msg.name), len(values), 'efforts' if kind == 'effort' else 'velocities')
            if not math.isfinite(values[k]):
                return "non-finite %s %r for actuator '%s'" % (kind, values[k], name)
            limit = self.effort_limits.get(name, self.max_velocity)
            if abs(values[k]) > IMPLAUSIBLE_FACTOR * limit:
                return "%s %g for actuator '%s' is beyond %g times its limit %g: not a set-point" \
                    % (kind, values[k], name, IMPLAUSIBLE_FACTOR, limit)
        return None

    def setpoint_of(self, msg, k):
        """The clamped set-point msg gives the k-th actuator it names."""
        name = msg.name[k]
        if name in self.effort_limits:
            limit = self.effort_limits[name]
            return max(-limit, min(limit, msg.effort[k]))
        return max(-self.max_velocity, min(self.max_velocity, msg.velocity[k]))

    def on_command(self, msg):
        with self.lock:
            self.take_command(msg)
            if self.lockstep:
                # Only the named publisher's messages count (docs/lockstep.md): a stray one
                # stamped ahead would otherwise satisfy every wait until its stamp.
                key = (self.command_topic, msg._connection_header['callerid'])
                self.received[key] = max(msg.header.stamp.to_nsec(), self.received.get(key, -1))
                self.work_if_ready()

    def take_command(self, msg):
        """With the lock held: checks the command and follows its set-points."""
        now = self.command_time(msg)
        reason = self.rejection(msg)
        if reason is not None:
            self.rejected += 1
            self.last_rejection = reason
            wall = time.time()
            self.rejection_times.append(wall)
            self.last_rejection_wall = wall
            self.accepted_since_rejection = False
            rospy.logerr_throttle(1.0, 'loopback hardware: command rejected: ' + reason)
            return
        self.advance(now)
        for k, name in enumerate(msg.name):
            i = self.names.index(name)
            self.setpoints[i] = self.setpoint_of(msg, k)
            requested = msg.effort[k] if name in self.effort_limits else msg.velocity[k]
            if self.setpoints[i] != requested:
                self.saturations[i] += 1
            if name in self.effort_limits:
                self.efforts[i] = self.setpoints[i]
        self.accepted += 1
        self.accepted_since_rejection = True
        self.last_accepted = now
        self.timed_out = False

    def on_e_stop(self, msg):
        with self.lock:
            if msg.data == self.e_stopped:
                return
            now = self.step_time if self.lockstep and self.step_time is not None else rospy.get_time()
            self.advance(now)
            self.e_stopped = msg.data
            self.setpoints = [0.0] * len(self.names)
            self.efforts = [0.0] * len(self.names)
            if msg.data:
                self.velocities = [0.0] * len(self.names)
                rospy.logerr('loopback hardware: e-stop engaged')
            else:
                rospy.logwarn('loopback hardware: e-stop released')
            self.publish(now)
        self.updater.force_update()

    def on_timer(self, _event):
        now = rospy.get_time()
        with self.lock:
            self.advance(now)
            self.publish(now)
        self.updater.update()

    def publish(self, now, stamp=None):
        state = JointState(name=list(self.names), position=list(self.positions),
                           velocity=list(self.velocities), effort=list(self.efforts))
        state.header.stamp = stamp if stamp is not None else rospy.Time.from_sec(now)
        self.state_pub.publish(state)

    def escalate(self, status):
        """ERROR above 20 rejections a second, WARN until good commands have been accepted for
        2 s after the last rejection (docs/hardware_interface.md, /diagnostics)."""
        wall = time.time()
        while self.rejection_times and self.rejection_times[0] <= wall - 1.0:
            self.rejection_times.popleft()
        rate = float(len(self.rejection_times))
        status.add(rospy.resolve_name('actuators/command') + ' rejected per second', str(rate))
        if self.last_rejection_wall is None or (self.accepted_since_rejection
                                                and wall - self.last_rejection_wall >= 2.0):
            return
        level = DiagnosticStatus.ERROR if rate > 20.0 else DiagnosticStatus.WARN
        status.mergeSummary(level, 'bad messages on %s (%g/s, %d in all): %s' % (
            rospy.resolve_name('actuators/command'), rate, self.rejected, self.last_rejection))

    def diagnose(self, status):
        with self.lock:
            if self.e_stopped:
                status.summary(DiagnosticStatus.ERROR, 'e-stop engaged')
            elif self.timed_out:
                status.summary(DiagnosticStatus.WARN, 'command timeout: actuators brought to rest')
            elif self.last_accepted is None:
                status.summary(DiagnosticStatus.OK, 'waiting for the first command')
            else:
                status.summary(DiagnosticStatus.OK, 'following commands')
            self.escalate(status)
            status.add('accepted commands', str(self.accepted))
            status.add('clock jumps', str(self.clock_jumps))
            status.add('rejected commands', str(self.rejected))
            status.add('last rejection', self.last_rejection)
            status.add('command timeout [s]', str(self.timeout))
            age = (rospy.get_time() - self.last_accepted if self.last_accepted is not None
                   else float('nan'))
            status.add('command age [s]', str(age))
            for i, name in enumerate(self.names):
                if name in self.effort_limits:
                    status.add(name + ' set-point, effort [N m or N]',
                               '%.6g, %.6g' % (self.setpoints[i], self.efforts[i]))
                else:
                    status.add(name + ' set-point, velocity [rad/s]',
                               '%.6g, %.6g' % (self.setpoints[i], self.velocities[i]))
                status.add(name + ' saturated set-points', str(self.saturations[i]))
        return status


def main():
    rospy.init_node('loopback_hardware')
    try:
        LoopbackHardware()
    except ParameterError as error:
        rospy.logfatal('%s: %s', rospy.get_name(), error)
        sys.exit(1)
    rospy.spin()


if __name__ == '__main__':
    main()
