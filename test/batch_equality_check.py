#!/usr/bin/env python3
"""Runs a stack in lock-step on its own ROS master, recorded to a bag, runs `sphere_sim` on the
same scenario with the stack's sampling (--loop sampled), and asserts that every message of the
stack equals the batch run's row of the same time since the first stamp, within 1e-9
(docs/lockstep.md, "Equal to the batch run"; issue 19 item 4). The goal is exactly 0: the batch
run calls the nodes' own core code in the order of a lock-step step.

As a rostest node (test/batch_equality_terrain.test) the parameters are private (~stack,
~duration, ~args); from a shell:
    batch_equality_check.py --stack terrain --duration 200 [-- launch args]
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import rosbag
import rospkg

from lockstep_repeat_check import run_stack

PKG = 'spherical_robots'
BOUND = 1e-9


def sphere_sim():
    """The batch tool of the package the stack runs from (installed beside this program)."""
    here = os.path.dirname(os.path.realpath(__file__))
    candidate = os.path.join(here, 'sphere_sim')
    if os.access(candidate, os.X_OK):
        return candidate
    import roslib.packages
    return roslib.packages.find_node(PKG, 'sphere_sim')[0]


def read_csv(path):
    """Rows by time since the first step [ns] (the CSV's t, written exactly as the stack's)."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {int(round(float(r['t']) * 1e9)): {k: float(v) for k, v in r.items()} for r in rows}


def terrain_messages(bag_path, ns):
    """Per topic: time since the first terrain_state [ns] -> {CSV column: value}."""
    states, errors = {}, {}
    with rosbag.Bag(bag_path) as bag:
        for topic, msg, _ in bag.read_messages(topics=['/%s/terrain_state' % ns,
                                                       '/%s/tracking_error' % ns]):
            stamp = msg.header.stamp.to_nsec()
            if topic.endswith('terrain_state'):
                states[stamp] = {
                    'x0': msg.contact_point.x, 'y0': msg.contact_point.y,
                    'z0': msg.contact_point.z, 'cx': msg.centre.x, 'cy': msg.centre.y,
                    'cz': msg.centre.z, 'psi': msg.psi, 'phi': msg.phi,
                    'roll_rate': msg.roll_rate, 'lateral_rate': msg.lateral_rate,
                    'turn_rate': msg.turn_rate}
            else:
                errors[stamp] = {'xd': msg.desired.x, 'yd': msg.desired.y, 'zd': msg.desired.z,
                                 'e_norm': msg.error_norm, 'zeta': msg.zeta}
    first = min(states)
    return ({k - first: v for k, v in states.items()}, {k - first: v for k, v in errors.items()})


def launch_value(args, name, default):
    for a in args:
        if a.startswith(name + ':='):
            return a.split(':=', 1)[1]
    return default


def compare_terrain(duration, extra_args, workdir):
    bag = os.path.join(workdir, 'terrain.bag')
    run_stack('terrain', duration, extra_args, bag, 0)
    states, errors = terrain_messages(bag, launch_value(extra_args, 'ns', 'sphere'))
    out = os.path.join(workdir, 'terrain.csv')
    command = [sphere_sim(), 'terrain', '--loop', 'sampled', '--duration', '%g' % duration,
               '--log-rate', '50', '--out', out,
               '--robot', launch_value(extra_args, 'robot', '3R'),
               '--path', launch_value(extra_args, 'path', 'circle'),
               '--model', launch_value(extra_args, 'model', 'paper'),
               '--law', launch_value(extra_args, 'law', 'smooth'),
               '--config', rospkg.RosPack().get_path(PKG)]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    rows = read_csv(out)
    report = []
    for topic, messages in (('terrain_state', states), ('tracking_error', errors)):
        expected = len(rows)
        missing = sorted(set(rows) - set(messages))
        if len(messages) != expected or missing:
            raise AssertionError('%s: %d messages, %d batch rows; first missing at %s s'
                                 % (topic, len(messages), expected,
                                    missing[0] * 1e-9 if missing else '-'))
        worst, where, column = 0.0, 0, ''
        for stamp, fields in messages.items():
            for name, value in fields.items():
                difference = abs(value - rows[stamp][name])
                if difference > worst:
                    worst, where, column = difference, stamp, name
        report.append('%-15s %6d messages, largest difference from the batch run %.3g (%s at %g s)'
                      % (topic, len(messages), worst, column or '-', where * 1e-9))
        if not worst <= BOUND:
            raise AssertionError('the stack differs from its batch run beyond %g:\n%s'
                                 % (BOUND, '\n'.join(report)))
    return '\n'.join(report)


STACKS = {'terrain': compare_terrain}


class BatchEquality(unittest.TestCase):
    def test_stack_equals_its_batch_run(self):
        import rospy
        rospy.init_node('batch_equality_check', anonymous=True)
        stack = rospy.get_param('~stack', 'terrain')
        duration = float(rospy.get_param('~duration', 200.0))
        extra_args = str(rospy.get_param('~args', '')).split()
        workdir = tempfile.mkdtemp(prefix='batch_equality.')
        print(STACKS[stack](duration, extra_args, workdir))
        shutil.rmtree(workdir, ignore_errors=True)


def main():
    if any(a.startswith('__name:=') for a in sys.argv):  # started by rostest
        import rostest
        rostest.rosrun(PKG, 'batch_equality_check', BatchEquality)
        return
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--stack', choices=sorted(STACKS), default='terrain')
    parser.add_argument('--duration', type=float, default=200.0)
    parser.add_argument('args', nargs='*', help='launch arguments, e.g. robot:=RS path:=diamond')
    options = parser.parse_args()
    workdir = tempfile.mkdtemp(prefix='batch_equality.')
    try:
        print(STACKS[options.stack](options.duration, options.args, workdir))
        print('equal: every message of the stack equals its batch run')
    except AssertionError as e:
        sys.exit('NOT equal: %s (files in %s)' % (e, workdir))
    shutil.rmtree(workdir, ignore_errors=True)


if __name__ == '__main__':
    main()
