#!/usr/bin/env python3
"""Runs one stack twice in lock-step, one run after the other, each on its own ROS master and
recorded to a bag, and asserts that the two runs published the same messages, value for value
(docs/lockstep.md, "Repeatable"). The second run can have busy loops hogging the CPU beside it,
and launch arguments of its own: with nodelet:=true it checks that the stack as nodelets
publishes what it publishes as processes. The bags must also hold every message the loop
publishes: as many as the step count says.

As a rostest node (test/lockstep_nodelet_terrain.test) the parameters are private (~stack,
~duration, ~busy_loops, ~args, ~second_args); from a shell:
    lockstep_repeat_check.py --stack terrain --duration 20 --busy-loops 2 \
        [--second-args nodelet:=true] [-- launch args]
"""
import argparse
import io
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import rosbag

from spherical_robots_testing import free_port, launch_file

PKG = 'spherical_robots'

# Per stack: its namespace, the topics compared, the topic whose count is checked against the
# step count with its rate [Hz], and whether the bag must hold every message. Norma's 1 kHz
# topics overflow rosbag record's subscriber queue (100 messages, fixed in rosbag) whenever the
# recorder is descheduled for 0.1 s, even at real time with busy loops beside it: there the
# messages of the steps both bags hold are compared, and the losses reported (docs/lockstep.md).
STACKS = {
    'terrain': ('sphere', ['odom', 'terrain_state', 'actuators/command', 'actuators/state',
                           'tracking_error', 'target'], ('odom', 50.0), True),
    'norma': ('norma', ['odom', 'norma_state', 'joint_states', 'actuators/command',
                        'actuators/state', 'tracking_error'], ('norma_state', 1000.0), False),
    'roller': ('roller', ['odom', 'terrain_state', 'drive/command', 'actuators/command',
                          'actuators/state', 'drive/state', 'roller_drive', 'tracking_error'],
               ('odom', 50.0), True),
    'rotor': ('rotor', ['odom', 'joint_states', 'actuators/command', 'actuators/state'],
              ('odom', 50.0), True),
    # The goals too: the goal sequence is a participant and sends each at a step, stamped with it.
    'freebot': ('freebot', ['freebot_state', 'actuators/command', 'actuators/state', 'ik_target',
                            'move_freebot/goal'], ('freebot_state', 100.0), True),
}
# The rotor stack's planner starts its manoeuvre itself (execute:=true, the default), at its first
# command period; the FreeBOT stack's goal sequence is a participant of the loop.


def run_stack(stack, duration, extra_args, bag, busy_loops):
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI='http://localhost:%d' % port)
    env['ROS_HOME'] = os.path.dirname(bag)
    busy = [subprocess.Popen(['yes'], stdout=subprocess.DEVNULL) for _ in range(busy_loops)]
    try:
        command = ['roslaunch', '-p', str(port), launch_file('%s_stack.launch' % stack),
                   'duration:=%g' % duration, 'record:=%s' % bag] + extra_args
        with open(bag + '.log', 'w') as log:
            child = subprocess.run(command, env=env, stdout=log, stderr=subprocess.STDOUT,
                                   timeout=60 + 20 * duration)
        if child.returncode != 0:
            with open(bag + '.log') as log:
                tail = log.readlines()[-20:]
            raise AssertionError('%s failed with %d; the end of its log %s:\n%s'
                                 % (' '.join(command), child.returncode, bag + '.log', ''.join(tail)))
    finally:
        for b in busy:
            b.kill()
            b.wait()


def serialized(msg):
    """The message's bytes with header.seq cleared (a publisher's counter, not the loop's data)."""
    if hasattr(msg, 'header'):
        msg.header.seq = 0
    out = io.BytesIO()
    msg.serialize(out)
    return out.getvalue()


def messages(bag_path, topics):
    """Per topic: stamp [ns] -> the message's bytes (the loop publishes one per topic and step)."""
    result = {topic: {} for topic in topics}
    with rosbag.Bag(bag_path) as bag:
        for topic, msg, _ in bag.read_messages(topics=topics):
            result[topic][msg.header.stamp.to_nsec()] = serialized(msg)
    return result


def transforms(bag_path, prefix):
    """The plant's /tf messages of the stack's frames (odom -> base_link, and base_link -> shell,
    heading of the terrain robots; FreeBOT's link<i> -> link<i+1>; the ones between a robot's
    links come from robot_state_publisher, an observer, which may drop joint_states it falls
    behind on), as (child frame, stamp, translation, rotation)."""
    plant_children = (prefix + 'shell', prefix + 'heading')
    out = []
    with rosbag.Bag(bag_path) as bag:
        for _, msg, _ in bag.read_messages(topics=['/tf']):
            for t in msg.transforms:
                if (t.header.frame_id in (prefix + 'odom', prefix + 'link0')
                        or t.child_frame_id in plant_children
                        or t.child_frame_id.startswith(prefix + 'link')):
                    tr, rot = t.transform.translation, t.transform.rotation
                    out.append((t.child_frame_id, t.header.stamp.to_nsec(),
                                tr.x, tr.y, tr.z, rot.x, rot.y, rot.z, rot.w))
    return out


def compare(stack, duration, extra_args, busy_loops, workdir, second_args=()):
    ns, topics, (count_topic, rate), lossless = STACKS[stack]
    names = ['/%s/%s' % (ns, t) for t in topics]
    bags = [os.path.join(workdir, 'run%d.bag' % i) for i in (1, 2)]
    run_stack(stack, duration, extra_args, bags[0], 0)
    run_stack(stack, duration, extra_args + list(second_args), bags[1], busy_loops)
    first, second = (messages(b, names) for b in bags)
    report = []
    for name in names:
        a, b = first[name], second[name]
        common = set(a) & set(b)
        same = sum(1 for stamp in common if a[stamp] == b[stamp])
        report.append('%-32s %7d / %7d messages, %7d of the same steps identical'
                      % (name, len(a), len(b), same))
        if same != len(common) or len(common) < 0.5 * max(len(a), len(b)):
            raise AssertionError('runs differ on %s:\n%s' % (name, '\n'.join(report)))
        if lossless and len(a) != len(b):
            raise AssertionError('a bag lost messages on %s:\n%s' % (name, '\n'.join(report)))
    tf = [transforms(b, ns + '/') for b in bags]
    report.append('%-32s %7d / %7d transforms' % ('/tf (%s/*)' % ns, len(tf[0]), len(tf[1])))
    common = set(tf[0]) & set(tf[1])
    if (lossless and tf[0] != tf[1]) or len(common) < 0.5 * len(tf[0]) or not tf[0]:
        raise AssertionError('runs differ on /tf:\n%s' % '\n'.join(report))
    expected = int(round(duration * rate))
    recorded = len(first['/%s/%s' % (ns, count_topic)])
    report.append('%s: %d recorded, %d expected (%g s at %g Hz)' % (count_topic, recorded, expected,
                                                                    duration, rate))
    if lossless and abs(recorded - expected) > 1:
        raise AssertionError('the bag lost messages:\n%s' % '\n'.join(report))
    return '\n'.join(report)


class LockstepRepeatability(unittest.TestCase):
    def test_two_runs_publish_the_same_messages(self):
        import rospy
        rospy.init_node('lockstep_repeat_check', anonymous=True)
        stack = rospy.get_param('~stack', 'terrain')
        duration = float(rospy.get_param('~duration', 20.0))
        busy_loops = int(rospy.get_param('~busy_loops', 2))
        extra_args = str(rospy.get_param('~args', '')).split()
        second_args = str(rospy.get_param('~second_args', '')).split()
        workdir = tempfile.mkdtemp(prefix='lockstep_repeat.')
        print(compare(stack, duration, extra_args, busy_loops, workdir, second_args))
        shutil.rmtree(workdir, ignore_errors=True)


def main():
    if any(a.startswith('__name:=') for a in sys.argv):  # started by rostest
        import rostest
        rostest.rosrun(PKG, 'lockstep_repeat_check', LockstepRepeatability)
        return
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--stack', choices=sorted(STACKS), default='terrain')
    parser.add_argument('--duration', type=float, default=20.0)
    parser.add_argument('--busy-loops', type=int, default=2)
    parser.add_argument('--second-args', nargs='+', default=[], metavar='ARG',
                        help='launch arguments of the second run only, e.g. nodelet:=true')
    parser.add_argument('args', nargs='*', help='launch arguments, e.g. robot:=RS path:=diamond')
    options = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix='lockstep_repeat.')
    try:
        print(compare(options.stack, options.duration, options.args, options.busy_loops, workdir,
                      options.second_args))
        print('repeatable: the two runs published the same messages')
    except AssertionError as e:
        sys.exit('NOT repeatable: %s (bags in %s)' % (e, workdir))
    shutil.rmtree(workdir, ignore_errors=True)


if __name__ == '__main__':
    main()
