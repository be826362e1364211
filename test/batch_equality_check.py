#!/usr/bin/env python3
"""Runs a stack in lock-step (the default clock) and `sphere_sim` on the same scenario as the
stack samples it, and asserts that every state the stack publishes equals the batch run's CSV row
at the same time since the first stamp, within a bound (issue 19 item 4; docs/lockstep.md, "Equal
to the batch run"). The goal is bit-identity: the batch runs the nodes' own core code in their
order with their times, so the figure reported is normally 0.

The stack runs on a ROS master of its own (a free port) while this process subscribes to its
state topic with an unbounded queue; the launch argument wait_for_subscribers makes time start
only once this checker is connected, so it sees every state from the first. In lock-step the
results do not depend on the machine's load: there is no timing assert here.

As a rostest node (test/norma_batch_equality.test) and from a shell alike:
    batch_equality_check.py --stack norma --duration 60 [--bound 1e-9] [--sphere-sim PATH] \
        [-- launch args, e.g. nodelet:=true]
"""
import argparse
import csv
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import rosgraph
import roslib.packages
import rospkg

PKG = 'spherical_robots'


class StackCase:
    """What is compared for one stack: its launch file and arguments, its namespace and state
    topic, the batch run that replays it, and which message field equals which CSV column (with
    its unit: the bound applies to lengths in metres; angles and rates are reported beside)."""

    def __init__(self, launch, launch_args, ns, topic, message_type, sphere_sim_args, fields):
        self.launch = launch
        self.launch_args = launch_args
        self.ns = ns
        self.topic = topic
        self.message_type = message_type
        self.sphere_sim_args = sphere_sim_args
        self.fields = fields  # [(name, value of a message, CSV column, unit)]


def norma_case(duration):
    from spherical_robots.msg import NormaState
    fields = [('x', lambda m: m.x, 'X', 'm'), ('y', lambda m: m.y, 'Y', 'm'),
              ('psi', lambda m: m.psi, 'psi', 'rad')]
    for i, (coordinate, unit) in enumerate([('theta', 'rad'), ('alpha', 'rad'), ('phi', 'rad'),
                                            ('delta', 'm')]):
        fields.append(('q[%d]' % i, lambda m, i=i: m.q[i], coordinate, unit))
        fields.append(('qd[%d]' % i, lambda m, i=i: m.qd[i], coordinate + 'd', unit + '/s'))
    return StackCase(
        launch='norma_stack.launch',
        launch_args=['controller:=tracking', 'duration:=%g' % duration],
        ns='norma', topic='norma_state', message_type=NormaState,
        sphere_sim_args=['norma', '--loop', 'sampled', '--controller', 'tracking',
                         '--duration', '%g' % duration, '--log-rate', '1000'],
        fields=fields)


# The stacks this check knows; terrain is to join with its own sampled sphere_sim run.
STACKS = {'norma': norma_case}


def free_port():
    with socket.socket() as s:
        s.bind(('localhost', 0))
        return s.getsockname()[1]


def launch_file(name):
    """By its full path, as $(find) resolves it (lockstep_repeat_check.py says why)."""
    return os.path.join(rospkg.RosPack().get_path(PKG), 'launch', name)


def find_sphere_sim():
    found = roslib.packages.find_node(PKG, 'sphere_sim')
    if not found:
        raise AssertionError('sphere_sim of %s not found (build and source the workspace, or '
                             'pass --sphere-sim PATH)' % PKG)
    return found[0]


def batch_rows(sphere_sim, case, workdir):
    """The CSV rows by time since the first step [ns]."""
    out = os.path.join(workdir, 'batch.csv')
    command = [sphere_sim] + case.sphere_sim_args + ['--out', out]
    started = time.time()
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        raise AssertionError('%s failed with %d: %s' % (' '.join(command), run.returncode,
                                                        run.stderr.strip()))
    with open(out) as f:
        rows = {int(round(float(row['t']) * 1e9)): row for row in csv.DictReader(f)}
    return rows, time.time() - started


class StateCollector:
    """Every state message of the stack, in arrival order, as (stamp [ns], message)."""

    def __init__(self, case, master_uri):
        import rospy
        os.environ['ROS_MASTER_URI'] = master_uri
        rospy.init_node('batch_equality_check', anonymous=True, disable_signals=True)
        self.states = []
        self.lock = threading.Lock()
        self.subscriber = rospy.Subscriber('/%s/%s' % (case.ns, case.topic), case.message_type,
                                           self.on_state, queue_size=None, tcp_nodelay=True)

    def on_state(self, msg):
        with self.lock:
            self.states.append((msg.header.stamp.to_nsec(), msg))

    def count(self):
        with self.lock:
            return len(self.states)


def wait_for_master(uri, timeout):
    master = rosgraph.Master('/batch_equality_check', master_uri=uri)
    deadline = time.time() + timeout
    while not master.is_online():
        if time.time() > deadline:
            raise AssertionError('the stack\'s master %s did not come up in %g s' % (uri, timeout))
        time.sleep(0.2)


def run_stack(case, duration, extra_args, workdir):
    """Launches the stack on its own master, collects its states until it ends. Returns them and
    the wall time the run took."""
    port = free_port()
    uri = 'http://localhost:%d' % port
    env = dict(os.environ, ROS_MASTER_URI=uri, ROS_HOME=workdir)
    command = (['roslaunch', '-p', str(port), launch_file(case.launch)] + case.launch_args +
               extra_args + ['wait_for_subscribers:=2'])  # its controller and this checker
    log_path = os.path.join(workdir, 'stack.log')
    started = time.time()
    with open(log_path, 'w') as log:
        child = subprocess.Popen(command, env=env, stdout=log, stderr=subprocess.STDOUT)
        try:
            wait_for_master(uri, 60)
            collector = StateCollector(case, uri)
            returncode = child.wait(timeout=120 + 20 * duration)
        finally:
            if child.poll() is None:
                child.terminate()
                child.wait()
    wall = time.time() - started
    if returncode != 0:
        with open(log_path) as log:
            tail = log.readlines()[-20:]
        raise AssertionError('%s failed with %d; the end of its log %s:\n%s'
                             % (' '.join(command), returncode, log_path, ''.join(tail)))
    # The last messages may still be in this process's queue: wait until none has come for 2 s.
    last = -1
    while collector.count() != last:
        last = collector.count()
        time.sleep(2.0)
    collector.subscriber.unregister()
    return sorted(collector.states, key=lambda s: s[0]), wall


def compare(case_name, duration, bound, sphere_sim, extra_args, workdir):
    case = STACKS[case_name](duration)
    rows, batch_wall = batch_rows(sphere_sim, case, workdir)
    states, stack_wall = run_stack(case, duration, extra_args, workdir)
    report = ['%s: %d states from the stack (%.1f s of wall time), %d rows from sphere_sim '
              '(%.2f s)' % (case_name, len(states), stack_wall, len(rows), batch_wall)]
    if not states:
        raise AssertionError('no state from the stack\n' + '\n'.join(report))
    first = states[0][0]
    largest = {}  # field -> (difference, time since the first stamp [ns])
    missing = []
    for stamp, msg in states:
        row = rows.get(stamp - first)
        if row is None:
            missing.append(stamp - first)
            continue
        for name, value, column, _ in case.fields:
            difference = abs(value(msg) - float(row[column]))
            if difference > largest.get(name, (-1.0, 0))[0]:
                largest[name] = (difference, stamp - first)
    for name, _, column, unit in case.fields:
        difference, at = largest[name]
        report.append('  %-6s (%-6s) max |stack - batch| %.3g %s at %.3f s'
                      % (name, column, difference, unit, at * 1e-9))
    length_max = max(largest[name][0] for name, _, _, unit in case.fields if unit == 'm')
    report.append('max difference in metres: %.3g m (bound %g m)' % (length_max, bound))
    if missing:
        raise AssertionError('%d states at times the batch run has no row for (the first at %.3f s)'
                             '\n%s' % (len(missing), missing[0] * 1e-9, '\n'.join(report)))
    if len(states) != len(rows) or len(set(s[0] for s in states)) != len(states):
        raise AssertionError('the stack published %d states (%d stamps), the batch run has %d rows: '
                             'a state was lost, repeated or is extra\n%s'
                             % (len(states), len(set(s[0] for s in states)), len(rows),
                                '\n'.join(report)))
    if length_max > bound:
        raise AssertionError('stack and batch run differ\n' + '\n'.join(report))
    return '\n'.join(report)


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--stack', choices=sorted(STACKS), default='norma')
    parser.add_argument('--duration', type=float, default=60.0, help='simulated seconds')
    parser.add_argument('--bound', type=float, default=1e-9,
                        help='largest difference allowed in any length [m]')
    parser.add_argument('--sphere-sim', help='the sphere_sim to run (default: the package\'s)')
    parser.add_argument('--keep', action='store_true', help='keep the work directory')
    parser.add_argument('launch_args', nargs='*', metavar='ARG',
                        help='further launch arguments, e.g. nodelet:=true')
    options = parser.parse_known_args(argv)[0]  # rostest adds --gtest_output=, --text
    # and the remappings __name:=, __log:= of a node
    options.launch_args = [a for a in options.launch_args if not a.startswith('__')]
    return options


def check(options):
    workdir = tempfile.mkdtemp(prefix='batch_equality.')
    try:
        print(compare(options.stack, options.duration, options.bound,
                      options.sphere_sim or find_sphere_sim(), options.launch_args, workdir))
    except AssertionError:
        print('work directory kept: %s' % workdir)
        raise
    if not options.keep:
        shutil.rmtree(workdir, ignore_errors=True)


class BatchEquality(unittest.TestCase):
    def test_every_state_equals_the_batch_run(self):
        check(parse(sys.argv[1:]))


def main():
    if any(a.startswith('__name:=') for a in sys.argv):  # started by rostest
        import rostest
        rostest.rosrun(PKG, 'batch_equality_check', BatchEquality)
        return
    try:
        check(parse(sys.argv[1:]))
    except AssertionError as e:
        sys.exit('NOT equal: %s' % e)


if __name__ == '__main__':
    main()
