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

With --path-poses N (terrain) the stack follows no built-in path (path:=topic): this checker sends
it the circle of config/terrain.yaml as a latched nav_msgs/Path of N + 1 poses over one lap, timed,
before time starts, and the batch run follows the built-in circle (test/terrain_path_topic.test).

As a rostest node (test/{terrain,roller,norma,rotor}_batch_equality.test) and from a shell alike:
    batch_equality_check.py --stack terrain|roller|norma|rotor [--duration S] [--bound 1e-9] \
        [--path-poses N] [--sphere-sim PATH] [-- launch args, e.g. robot:=RS path:=diamond]
Launch arguments the batch run also takes (terrain: robot, path, model, law, actuator_models;
roller: path, law, actuator_models; rotor: k, steps, target, curve_rate, actuator_time_constant,
corrections, correction_tolerance, correction_tilt_tolerance, actuator_models) are passed to
sphere_sim too.
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import rosgraph
import roslib.packages
import rospkg

from spherical_robots_testing import free_port, launch_file

PKG = 'spherical_robots'


class StackCase:
    """What is compared for one stack: its launch file and arguments, its namespace, the batch run
    that replays it, and per topic which message field equals which CSV column (with its unit:
    the bound applies to lengths in metres; angles and rates are reported beside)."""

    def __init__(self, launch, launch_args, ns, topics, sphere_sim_args):
        self.launch = launch
        self.launch_args = launch_args
        self.ns = ns
        self.topics = topics  # [(topic, message type, [(name, value of a message, column, unit)])]
        self.sphere_sim_args = sphere_sim_args
        self.path_message = None  # a nav_msgs/Path to send the stack before time starts


def launch_value(args, name, default):
    """The value of launch argument `name` among args (NAME:=VALUE), or default."""
    for arg in args:
        if arg.startswith(name + ':='):
            return arg.split(':=', 1)[1]
    return default


def terrain_case(duration, extra_args, stack='terrain'):
    from nav_msgs.msg import Odometry
    from spherical_robots.msg import TerrainState, TrackingError

    state_fields = ([('contact_point.' + a, lambda m, a=a: getattr(m.contact_point, a), a + '0', 'm')
                     for a in 'xyz'] +
                    [('centre.' + a, lambda m, a=a: getattr(m.centre, a), 'c' + a, 'm') for a in 'xyz'] +
                    [(name, lambda m, name=name: getattr(m, name), name, unit)
                     for name, unit in (('psi', 'rad'), ('phi', 'rad'), ('roll_rate', 'rad/s'),
                                        ('lateral_rate', 'rad/s'), ('turn_rate', 'rad/s'))])
    # odom first: the topic whose subscribers time waits for, so this checker sees every state.
    odom_fields = [('pose.position.' + a, lambda m, a=a: getattr(m.pose.pose.position, a), 'c' + a, 'm')
                   for a in 'xyz']
    error_fields = ([('desired.' + a, lambda m, a=a: getattr(m.desired, a), a + 'd', 'm') for a in 'xyz'] +
                    [('error_norm', lambda m: m.error_norm, 'e_norm', 'm'),
                     ('zeta', lambda m: m.zeta, 'zeta', 'rad')])
    sphere_sim_args = ['terrain', '--loop', 'sampled', '--stack', stack, '--duration',
                       '%g' % duration, '--log-rate', '50',
                       '--config', rospkg.RosPack().get_path(PKG)]
    fixed = {'robot': '2R', 'model': 'rolling'} if stack == 'roller' else {}
    for name, option, default in (('robot', '--robot', '3R'), ('path', '--path', 'circle'),
                                  ('model', '--model', 'paper'), ('law', '--law', 'smooth')):
        sphere_sim_args += [option, fixed.get(name) or launch_value(extra_args, name, default)]
    models = launch_value(extra_args, 'actuator_models', '')
    if models:
        sphere_sim_args += ['--actuator-models', models]
    return StackCase(
        launch='%s_stack.launch' % stack, launch_args=['duration:=%g' % duration],
        ns=launch_value(extra_args, 'ns', 'sphere' if stack == 'terrain' else stack),
        topics=[('odom', Odometry, odom_fields), ('terrain_state', TerrainState, state_fields),
                ('tracking_error', TrackingError, error_fields)],
        sphere_sim_args=sphere_sim_args)


def norma_case(duration, extra_args):
    from nav_msgs.msg import Odometry
    from spherical_robots.msg import NormaState
    # odom first: the topic whose subscribers time waits for, so this checker sees every state.
    odom_fields = [('pose.position.x', lambda m: m.pose.pose.position.x, 'X', 'm'),
                   ('pose.position.y', lambda m: m.pose.pose.position.y, 'Y', 'm')]
    fields = [('x', lambda m: m.x, 'X', 'm'), ('y', lambda m: m.y, 'Y', 'm'),
              ('psi', lambda m: m.psi, 'psi', 'rad')]
    for i, (coordinate, unit) in enumerate([('theta', 'rad'), ('alpha', 'rad'), ('phi', 'rad'),
                                            ('delta', 'm')]):
        fields.append(('q[%d]' % i, lambda m, i=i: m.q[i], coordinate, unit))
        fields.append(('qd[%d]' % i, lambda m, i=i: m.qd[i], coordinate + 'd', unit + '/s'))
    return StackCase(
        launch='norma_stack.launch',
        # Capped: at the stack's own pace (5x, two 1 kHz topics) this checker, an observer in
        # rospy, can fall more than the publishers' 5,000-message queues behind when four
        # tests run at once on two cores (it lost 186 odom messages once). The cap changes no
        # value.
        launch_args=['controller:=tracking', 'duration:=%g' % duration, 'speedup:=2'],
        ns=launch_value(extra_args, 'ns', 'norma'),
        topics=[('odom', Odometry, odom_fields), ('norma_state', NormaState, fields)],
        sphere_sim_args=['norma', '--loop', 'sampled', '--controller', 'tracking',
                         '--duration', '%g' % duration, '--log-rate', '1000'])


def roller_case(duration, extra_args):
    return terrain_case(duration, extra_args, 'roller')


def rotor_case(duration, extra_args):
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import JointState
    pose_fields = ([(a, lambda m, a=a: getattr(m.pose.pose.position, a), a, 'm') for a in 'xy'] +
                   [('q' + a, lambda m, a=a: getattr(m.pose.pose.orientation, a), 'q' + a, '1')
                    for a in 'wxyz'])
    speed_fields = [('velocity[%d]' % i, lambda m, i=i: m.velocity[i], 'measured_%d' % (i + 1),
                     'rad/s') for i in range(2)]
    sphere_sim_args = ['rotor-execute', '--duration', '%g' % duration, '--log-rate', '50',
                       '--config', rospkg.RosPack().get_path(PKG)]
    for name, option in (('k', '--k'), ('steps', '--steps'), ('target', '--target'),
                         ('curve_rate', '--curve-rate'),
                         ('actuator_time_constant', '--actuator-time-constant'),
                         ('corrections', '--corrections'),
                         ('correction_tolerance', '--correction-tolerance'),
                         ('correction_tilt_tolerance', '--correction-tilt-tolerance'),
                         ('actuator_models', '--actuator-models')):
        value = launch_value(extra_args, name, '')
        if value:
            sphere_sim_args += [option, value]
    return StackCase(
        launch='rotor_stack.launch', launch_args=['duration:=%g' % duration],
        ns=launch_value(extra_args, 'ns', 'rotor'),
        topics=[('odom', Odometry, pose_fields), ('joint_states', JointState, speed_fields)],
        sphere_sim_args=sphere_sim_args)


def sampled_circle(poses):
    """config/terrain.yaml's circle as a nav_msgs/Path of poses + 1 timed poses over one lap (the
    last the first: a closed path), stamped from 0, in the controllers' fixed frame."""
    import yaml
    from geometry_msgs.msg import PoseStamped
    from nav_msgs.msg import Path
    import rospy
    with open(os.path.join(rospkg.RosPack().get_path(PKG), 'config', 'terrain.yaml')) as f:
        circle = yaml.safe_load(f)['terrain']['paths']['circle']
    radius, rate = float(circle['radius']), float(circle['angular_rate'])
    period = 2.0 * math.pi / rate
    msg = Path()
    msg.header.frame_id = 'map'
    for i in range(poses + 1):
        t = period * i / poses
        pose = PoseStamped()
        pose.header.frame_id = msg.header.frame_id
        pose.header.stamp = rospy.Time.from_sec(t)
        pose.pose.position.x = radius * math.cos(rate * t)
        pose.pose.position.y = radius * math.sin(rate * t)
        pose.pose.orientation.w = 1.0
        msg.poses.append(pose)
    return msg


STACKS = {'terrain': terrain_case, 'roller': roller_case, 'norma': norma_case, 'rotor': rotor_case}


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
    """Every message of the compared topics, in arrival order, as (stamp [ns], message) per topic."""

    def __init__(self, case, master_uri):
        import rospy
        os.environ['ROS_MASTER_URI'] = master_uri
        rospy.init_node('batch_equality_check', anonymous=True, disable_signals=True)
        self.messages = {topic: [] for topic, _, _ in case.topics}
        self.lock = threading.Lock()
        self.subscribers = [
            rospy.Subscriber('/%s/%s' % (case.ns, topic), message_type, self.on_message,
                             callback_args=topic, queue_size=None, tcp_nodelay=True)
            for topic, message_type, _ in case.topics]
        if case.path_message is not None:
            from nav_msgs.msg import Path
            # Latched: the controller takes it whenever it connects, and (path:=topic) joins
            # lock-step time only once it has it.
            self.path_publisher = rospy.Publisher('/%s/path' % case.ns, Path, queue_size=1,
                                                  latch=True)
            self.path_publisher.publish(case.path_message)

    def on_message(self, msg, topic):
        with self.lock:
            self.messages[topic].append((msg.header.stamp.to_nsec(), msg))

    def count(self):
        with self.lock:
            return sum(len(m) for m in self.messages.values())


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
    for subscriber in collector.subscribers:
        subscriber.unregister()
    return {topic: sorted(m, key=lambda s: s[0]) for topic, m in collector.messages.items()}, wall


def compare(case_name, duration, bound, sphere_sim, extra_args, workdir, path_poses=0):
    case = STACKS[case_name](duration, extra_args)
    if path_poses:
        if case_name != 'terrain' or launch_value(extra_args, 'path', 'circle') != 'circle':
            raise AssertionError('--path-poses sends the terrain stack its circle')
        case.launch_args.append('path:=topic')
        case.path_message = sampled_circle(path_poses)
    rows, batch_wall = batch_rows(sphere_sim, case, workdir)
    messages, stack_wall = run_stack(case, duration, extra_args, workdir)
    report = ['%s: %s from the stack (%.1f s of wall time), %d rows from sphere_sim (%.2f s)'
              % (case_name, ', '.join('%d %s' % (len(messages[t]), t) for t, _, _ in case.topics),
                 stack_wall, len(rows), batch_wall)]
    if path_poses:
        report.append('the stack followed the circle sent as a nav_msgs/Path of %d poses, the '
                      'batch run the built-in circle' % len(case.path_message.poses))
    if not all(messages.values()):
        raise AssertionError('a topic had no message\n' + '\n'.join(report))
    # Time since the stack's first step: the first state, which the checker sees (time starts
    # only once it is connected).
    first = messages[case.topics[0][0]][0][0]
    length_max = 0.0
    for topic, _, fields in case.topics:
        largest = {}  # field -> (difference, time since the first stamp [ns])
        missing = []
        for stamp, msg in messages[topic]:
            row = rows.get(stamp - first)
            if row is None:
                missing.append(stamp - first)
                continue
            for name, value, column, _ in fields:
                difference = abs(value(msg) - float(row[column]))
                if difference > largest.get(name, (-1.0, 0))[0]:
                    largest[name] = (difference, stamp - first)
        report.append(' %s:' % topic)
        for name, _, column, unit in fields:
            difference, at = largest.get(name, (float('nan'), 0))
            report.append('  %-16s (%-12s) max |stack - batch| %.3g %s at %.3f s'
                          % (name, column, difference, unit, at * 1e-9))
        length_max = max([length_max] + [largest[name][0] for name, _, _, unit in fields
                                         if unit == 'm' and name in largest])
        if missing:
            raise AssertionError('%d %s messages at times the batch run has no row for (the first '
                                 'at %.3f s)\n%s' % (len(missing), topic, missing[0] * 1e-9,
                                                     '\n'.join(report)))
        stamps = set(m[0] for m in messages[topic])
        if len(messages[topic]) != len(rows) or len(stamps) != len(rows):
            raise AssertionError('the stack published %d %s messages (%d stamps), the batch run '
                                 'has %d rows: a message was lost, repeated or is extra\n%s'
                                 % (len(messages[topic]), topic, len(stamps), len(rows),
                                    '\n'.join(report)))
    report.append('max difference in metres: %.3g m (bound %g m)' % (length_max, bound))
    if length_max > bound:
        raise AssertionError('stack and batch run differ\n' + '\n'.join(report))
    return '\n'.join(report)


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--stack', choices=sorted(STACKS), default='terrain')
    parser.add_argument('--duration', type=float, default=60.0, help='simulated seconds')
    parser.add_argument('--bound', type=float, default=1e-9,
                        help='largest difference allowed in any length [m]')
    parser.add_argument('--path-poses', type=int, default=0,
                        help='terrain: send the stack its circle as a nav_msgs/Path of this many '
                             'intervals (path:=topic)')
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
                      options.sphere_sim or find_sphere_sim(), options.launch_args, workdir,
                      options.path_poses))
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
