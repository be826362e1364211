#!/usr/bin/env python3
"""A stack under scripts/run_stack.py, on a master of its own, with two busy loops beside it (by
default; --busy-loops): how it ends (docs/conventions.md, "When a node dies").

    stack_supervision_check.py --stack terrain                       # a normal end
    stack_supervision_check.py --stack terrain --kill pure_pursuit_controller [--respawn]
    stack_supervision_check.py --stack terrain --kill hardware_interface --respawn --pause
    stack_supervision_check.py --stack norma --kill norma_plant --respawn -- controller:=tracking

* A normal end: exit status 0, and no "REQUIRED process [...] has died" on the output.
* --kill NODE (kill -9 at --at simulated seconds), respawn:=false: exit status 1 within
  FAILURE_BOUND of wall time of the kill, naming the node and the signal.
* --kill NODE --respawn: the node is back (a new process registered under its name), the run
  reaches its duration, exit status 0, no "REQUIRED", and |e_t| over the last WINDOW seconds is
  within the normal run's: the batch run of the same scenario (sphere_sim --loop sampled, what
  the stack in lock-step publishes when nothing dies, docs/lockstep.md) plus TRACKING_SLACK.
* --kill PLANT --respawn: run_stack.py restarts the plant from its checkpoint: its first odom is
  within one publication's motion of its last before the kill (not at the origin), /clock never
  goes back, and the run ends and tracks as above.
* --pause (with --kill hardware_interface --respawn): lock-step is paused before the kill and
  resumed once the new process has registered and subscribed, so that it is asked at the next
  step without a drop: its first state is at rest (nothing commanded it yet: zero velocities and
  efforts), it then ramps within its max_acceleration, and the run tracks as above.
It prints what it measured: the wall time from the kill to the end or to the node's return and to
its first new output, the simulated time without its output, and a RECOVERY line for
test/recovery_table.py.

As a rostest node (test/stack_supervision_*.test) its arguments are the <test>'s args.
"""
import argparse
import csv
import math
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import rosgraph
import rospy
import rosunit
from nav_msgs.msg import Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import JointState
from std_srvs.srv import Empty

from spherical_robots.msg import TrackingError
from spherical_robots_testing import free_port, pid_of

PKG = 'spherical_robots'
SOURCE = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
RUN_STACK = os.path.join(SOURCE, 'scripts', 'run_stack.py')
# [s] of wall time from a kill to run_stack.py's exit with respawn:=false: roslaunch's process
# monitor and run_stack.py's queue notice the death (0.1 s polls each; a stack of processes has no
# SETTLE), then roslaunch shuts the other processes down (SIGINT, SIGTERM after 15 s), plus 5 s for
# a busy machine.
FAILURE_BOUND = 0.2 + 15.0 + 5.0
WINDOW = 20.0  # [s] simulated, at the end of the run, where tracking is compared
# [m] how far the respawned run's worst |e_t| over WINDOW may be above the normal run's: the
# restarted controller's own state (its path progress, the smooth law's filters) starts afresh
# after a gap, and must have converged back onto the normal run's orbit.
TRACKING_SLACK = 1e-3

# Per stack: its namespace and the batch run of its normal scenario (sphere_sim subcommand and
# options, the CSV column of |e|).
STACKS = {
    'terrain': ('sphere', ['terrain', '--loop', 'sampled', '--stack', 'terrain', '--robot', '3R',
                           '--path', 'circle', '--law', 'smooth', '--model', 'paper'], 'e_norm'),
    'roller': ('roller', ['terrain', '--loop', 'sampled', '--stack', 'roller', '--robot', '2R',
                          '--path', 'circle', '--law', 'smooth', '--model', 'rolling'], 'e_norm'),
    'norma': ('norma', ['norma', '--loop', 'sampled', '--controller', 'tracking'], 'err'),
}
# The topic each node's work shows on, and its type: its gap after a kill is the simulated time
# without it.
WORK = {'pure_pursuit_controller': ('actuators/command', JointState),
        'norma_controller': ('actuators/command', JointState),
        'hardware_interface': ('actuators/state', JointState),
        'roller/pure_pursuit_controller': ('drive/command', JointState),
        'terrain_plant': ('odom', Odometry), 'norma_plant': ('odom', Odometry)}
# [s] of wall time for a restarted node to subscribe and have its subscriptions settle (1 s,
# docs/lockstep.md "Joining") before lock-step resumes, with --pause.
SETTLE_AFTER_RESTART = 3.0


class Options:
    stack, kill, respawn, pause, at, duration, busy_loops, args = (
        'terrain', None, False, False, 30.0, 120.0, 2, [])


def run_batch(duration):
    _, command, column = STACKS[Options.stack]
    out = os.path.join(tempfile.mkdtemp(), 'batch.csv')
    subprocess.run([sphere_sim()] + command + ['--duration', '%g' % duration, '--log-rate', '50',
                                               '--config', SOURCE, '--out', out],
                   check=True, stdout=subprocess.DEVNULL)
    with open(out) as f:
        return [(float(r['t']), float(r[column])) for r in csv.DictReader(f)]


def sphere_sim():
    import roslib.packages
    return roslib.packages.find_node(PKG, 'sphere_sim')[0]


class StackSupervision(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        ns = STACKS[Options.stack][0]
        port = free_port()
        uri = 'http://localhost:%d' % port
        cls.home = tempfile.mkdtemp(prefix='stack_supervision_')
        env = dict(os.environ, ROS_MASTER_URI=uri, ROS_HOME=cls.home)
        cls.busy = [subprocess.Popen(['yes'], stdout=subprocess.DEVNULL)
                    for _ in range(Options.busy_loops)]
        cls.log_path = os.path.join(cls.home, 'run_stack.log')
        log = open(cls.log_path, 'w')
        command = [RUN_STACK, '%s_stack.launch' % Options.stack,
                   'duration:=%g' % Options.duration,
                   'respawn:=%s' % ('true' if Options.respawn else 'false')] + Options.args
        start = time.time()
        cls.child = subprocess.Popen(command, env=env, stdout=log, stderr=subprocess.STDOUT,
                                     start_new_session=True)
        cls.kill_wall = cls.back_wall = cls.old_pid = cls.new_pid = None
        cls.work = []
        cls.clock = []
        cls.tracking = []  # (stamp, |e_t|) or for Norma (stamp, odom)
        try:
            if Options.kill:
                os.environ['ROS_MASTER_URI'] = uri
                while not rosgraph.is_master_online(uri) and time.time() < start + 120:
                    time.sleep(0.2)
                rospy.init_node('stack_supervision_check', disable_signals=True)
                node = '/%s/%s' % (ns, Options.kill)
                clock = cls.clock
                rospy.Subscriber('/clock', Clock, lambda m: clock.append(m.clock.to_sec()),
                                 queue_size=100000)
                # Its own subscription, not a bag: rosbag record, which keeps 100 messages per
                # topic, lost a third of them on this loaded machine.
                if Options.stack == 'norma':
                    rospy.Subscriber('/%s/odom' % ns, Odometry, lambda m: cls.tracking.append(
                        (m.header.stamp.to_sec(), m)), queue_size=100000)
                else:
                    rospy.Subscriber('/%s/tracking_error' % ns, TrackingError,
                                     lambda m: cls.tracking.append(
                                         (m.header.stamp.to_sec(), m.error_norm)),
                                     queue_size=100000)
                topic, kind = WORK.get('%s/%s' % (Options.stack, Options.kill), WORK[Options.kill])
                rospy.Subscriber('/%s/%s' % (ns, topic), kind,
                                 lambda m: cls.work.append((time.time(), m.header.stamp.to_sec(), m)),
                                 queue_size=100000)
                while (not clock or clock[-1] < Options.at) and cls.child.poll() is None:
                    time.sleep(0.01)
                if Options.pause:
                    rospy.ServiceProxy('/%s/lockstep/pause' % ns, Empty)()
                    time.sleep(1.0)  # the step in progress ends
                cls.old_pid = pid_of(node, uri)
                os.kill(cls.old_pid, signal.SIGKILL)
                cls.kill_wall = time.time()
                cls.kill_sim = clock[-1]
                while cls.child.poll() is None and Options.respawn and cls.back_wall is None:
                    pid = pid_of(node, uri)
                    if pid not in (None, cls.old_pid):
                        cls.new_pid, cls.back_wall = pid, time.time()
                    time.sleep(0.05)
                if Options.pause:
                    cls.max_acceleration = rospy.get_param(node + '/max_acceleration', None)
                    time.sleep(SETTLE_AFTER_RESTART)
                    rospy.ServiceProxy('/%s/lockstep/resume' % ns, Empty)()
            cls.status = cls.child.wait(timeout=60 + 2 * Options.duration)
            cls.end_wall = time.time()
        finally:
            if cls.child.poll() is None:
                os.killpg(cls.child.pid, signal.SIGKILL)
            for b in cls.busy:
                b.kill()
                b.wait()
            log.close()
        with open(cls.log_path) as f:
            cls.output = f.read()

    def report(self, what):
        sys.__stderr__.write("stack_supervision_check (%s): %s\n" % (Options.stack, what))

    def assertStatus(self, status):
        self.assertEqual(self.status, status, 'run_stack.py exited with %s; its output %s ends:\n%s'
                         % (self.status, self.log_path, self.output[-3000:]))

    def test_end(self):
        if Options.kill and not Options.respawn:
            self.assertStatus(1)
            self.assertIn('%s killed by signal 9' % Options.kill, self.output)
            took = self.end_wall - self.kill_wall
            self.report('kill -9 %s at %.1f s simulated: the stack ended, status 1, %.1f s of '
                        'wall time later' % (Options.kill, self.kill_sim, took))
            self.assertLess(took, FAILURE_BOUND)
        else:
            self.assertStatus(0)
            self.assertIn('the plant ended the stack normally', self.output)
        self.assertNotIn('REQUIRED process', self.output)

    def test_respawned_node_tracks_as_the_normal_run(self):
        if not (Options.kill and Options.respawn):
            self.skipTest('for --kill with --respawn')
        self.assertIsNotNone(self.new_pid, '%s did not come back' % Options.kill)
        # The largest gap between the stamps of its messages: the simulated time the loop ran
        # without it.
        stamps = [stamp for _, stamp, _ in self.work]
        gap, since = max((b - a, a) for a, b in zip(stamps, stamps[1:]) if a >= self.kill_sim - 1)
        first_back = next(wall for wall, _, _ in self.work if wall > self.back_wall)
        self.report('kill -9 %s at %.1f s simulated: back as pid %d after %.1f s of wall time, '
                    'publishing again after %.1f s; %.3f s of simulated time without its '
                    'messages from %.3f s' % (Options.kill, self.kill_sim, self.new_pid,
                                             self.back_wall - self.kill_wall,
                                             first_back - self.kill_wall, gap, since))
        errors = self.errors_at_end()
        normal = [e for t, e in run_batch(Options.duration) if t >= Options.duration - WINDOW]
        self.report('|e_t| over the last %g s: respawned run max %.6g m (%d samples), normal run '
                    'max %.6g m' % (WINDOW, max(errors), len(errors), max(normal)))
        self.report('RECOVERY stack=%s node=%s back=%.2f first_output=%.2f sim_gap=%.3f '
                    'e_max=%.6g e_normal=%.6g' % (Options.stack, Options.kill,
                                                  self.back_wall - self.kill_wall,
                                                  first_back - self.kill_wall, gap, max(errors),
                                                  max(normal)))
        self.assertGreater(len(errors), 0.9 * WINDOW * 50)
        self.assertLessEqual(max(errors), max(normal) + TRACKING_SLACK)

    def test_restarted_plant_resumes_where_it_was(self):
        if not (Options.respawn and Options.kill and Options.kill.endswith('_plant')):
            self.skipTest('for --kill PLANT with --respawn')
        self.assertIsNotNone(self.new_pid, '%s did not come back' % Options.kill)
        before = [(s, m) for w, s, m in self.work if w < self.back_wall]
        after = [(s, m) for w, s, m in self.work if w >= self.back_wall]
        self.assertTrue(before and after, 'no odom before the kill or after the restart')
        position = lambda m: (m.pose.pose.position.x, m.pose.pose.position.y)
        # One publication's motion: the largest distance between consecutive odom before the kill.
        step = max(math.dist(position(a), position(b)) for (_, a), (_, b) in zip(before, before[1:]))
        moved = math.dist(position(before[-1][1]), position(after[0][1]))
        self.report('kill -9 %s: last odom before the kill at %.3f s (%.4f, %.4f) m, first after '
                    'the restart at %.3f s (%.4f, %.4f) m: %.2e m apart, one publication moves '
                    'up to %.2e m' % ((Options.kill, before[-1][0]) + position(before[-1][1]) +
                                      (after[0][0],) + position(after[0][1]) + (moved, step)))
        self.assertLessEqual(moved, 2.0 * step + 1e-9)
        self.assertGreater(after[0][0], before[-1][0] - 0.05)
        back = [(a, b) for a, b in zip(self.clock, self.clock[1:]) if b < a]
        self.assertEqual(back, [], '/clock went back')

    def test_restarted_hardware_interface_is_at_rest_until_commanded(self):
        if not (Options.respawn and Options.pause and Options.kill == 'hardware_interface'):
            self.skipTest('for --kill hardware_interface --respawn --pause')
        self.assertIsNotNone(self.new_pid, 'the hardware interface did not come back')
        states = [(s, m) for w, s, m in self.work if w > self.back_wall]
        self.assertTrue(states, 'no actuator state from the restarted hardware interface')
        first = states[0][1]
        self.report('first state of the restarted hardware interface at %.3f s: velocities %s, '
                    'efforts %s' % (states[0][0], list(first.velocity), list(first.effort)))
        self.assertTrue(all(v == 0.0 for v in first.velocity), 'not at rest: %s' % first)
        self.assertTrue(all(e == 0.0 for e in first.effort), 'not at rest: %s' % first)
        acceleration = self.max_acceleration
        for (t0, a), (t1, b) in zip(states, states[1:]):
            for v0, v1 in zip(a.velocity, b.velocity):
                self.assertLessEqual(abs(v1 - v0), acceleration * (t1 - t0) + 1e-9,
                                     'a jump, not a ramp from rest, at %.3f s' % t1)

    @classmethod
    def errors_at_end(cls):
        if Options.stack == 'norma':
            return norma_path_errors(cls.tracking)
        return [e for t, e in cls.tracking if t >= Options.duration - WINDOW]


def norma_path_errors(odometry):
    """|e| over WINDOW at 50 Hz against the run's path of eq 52, timed from the first state (at
    one 1 ms step: lock-step's first), not against the controller's own reference
    (tracking_error): a controller that restarted its path clock tracks its own new path well,
    and only this shows it off the run's."""
    errors, start = [], 0.001
    for t, m in odometry:
        ticks = round((t - start) * 1000)
        if t >= Options.duration - WINDOW and ticks % 20 == 0:
            s = t - start
            errors.append(math.hypot(m.pose.pose.position.x - 2.0 * math.sin(0.01 * s),
                                     m.pose.pose.position.y - 1.5 * math.sin(0.02 * s)))
    return errors


def main(argv):
    parser = argparse.ArgumentParser()
    parser.add_argument('--stack', default='terrain', choices=sorted(STACKS))
    parser.add_argument('--kill', help='a node of the loop, relative to the stack namespace')
    parser.add_argument('--respawn', action='store_true')
    parser.add_argument('--pause', action='store_true',
                        help='pause lock-step for the kill, resume once the node is back')
    parser.add_argument('--at', type=float, default=30.0, help='[s] simulated')
    parser.add_argument('--duration', type=float, default=120.0, help='[s] simulated')
    parser.add_argument('--busy-loops', type=int, default=2,
                        help='busy loops (yes) beside the stack; the rostests give 0: the suite '
                             'is run beside busy loops as a whole (README), and two more in each of '
                             'eight tests, four at a time, cost the suite about 50 s of CPU')
    parser.add_argument('args', nargs='*', help='launch arguments NAME:=VALUE')
    # rostest adds where rosunit writes its results, and roslaunch the node's __name:= and __log:=.
    # Not rospy.myargv(), which drops every NAME:=VALUE, the launch arguments too (before, this
    # check ran every stack with its launch defaults: speedup:=10 and controller:=tracking lost).
    parsed = parser.parse_args([a for a in argv[1:]
                                if not a.startswith(('--gtest_output=', '__name:=', '__log:='))])
    Options.stack, Options.kill, Options.respawn = parsed.stack, parsed.kill, parsed.respawn
    Options.pause = parsed.pause
    Options.at, Options.duration, Options.busy_loops = parsed.at, parsed.duration, parsed.busy_loops
    Options.args = parsed.args
    rosunit.unitrun(PKG, 'stack_supervision_%s' % Options.stack, StackSupervision)


if __name__ == '__main__':
    main(sys.argv)
