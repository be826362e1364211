#!/usr/bin/python3
"""The two-rotor sphere's run (Svinin et al.) from a recorded rotor stack's bag: the centre's
driven path against the planned one (XY, as the paper's figure-eight figures), its distance and
attitude error to the plan's end over time, the rotor speeds commanded (eq 11 set-points) and
measured, and the rotor angles.

usage: plot_rotor_run.py BAG OUT.png [TITLE] [--ns /rotor]
e.g.   roslaunch spherical_robots rotor_stack.launch record:=/tmp/rotor.bag
       /usr/bin/python3 scripts/plot_rotor_run.py /tmp/rotor.bag /tmp/rotor.png

Topics under <ns> (a topic missing there is looked up by its message type): planned_path (the
plan, latched), odom (the plant's centre and attitude), actuators/command and actuators/state
(rotor_1, rotor_2 [rad/s]), joint_states (rotor angles [rad]). Prints the end errors.
The planned path is the plan from the zero state (planner's convention), as the stack runs it:
for an execution started elsewhere, the start mark and the plan's end are not where it drove.
"""
import math
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

# The sibling module, also when a catkin devel-space relay runs this file (it sets __file__).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from plot_support import (JOINT_STATE, PATH, RunError, attitude_angle, find_topic,  # noqa: E402
                          open_bag, read_or_exit, run_figure_arguments)

ODOMETRY = 'nav_msgs/Odometry'


def read_bag(path, ns):
    run = {'planned': [], 'driven': [], 'command': {}, 'measured': {}, 'angles': {}}
    with open_bag(path) as (bag, topics):
        names = {
            'planned': find_topic(topics, ns, 'planned_path', PATH),
            'driven': find_topic(topics, ns, 'odom', ODOMETRY),
            'command': ns.rstrip('/') + '/actuators/command',
            'measured': ns.rstrip('/') + '/actuators/state',
            'angles': ns.rstrip('/') + '/joint_states'}
        if names['planned'] is None or names['driven'] is None:
            raise RunError('%s has no %s or no %s (topics: %s)' % (
                path, PATH, ODOMETRY, ', '.join(sorted(topics)) or 'none'))
        kind = {topic: key for key, topic in names.items()}
        for topic, msg, _ in bag.read_messages(topics=sorted(t for t in kind if t in topics)):
            key = kind[topic]
            if key == 'planned':
                run['planned'] = [pose_tuple(p.pose) for p in msg.poses]
            elif key == 'driven':
                run['driven'].append((msg.header.stamp.to_sec(),) + pose_tuple(msg.pose.pose))
            elif topics[topic] == JOINT_STATE:
                values = msg.position if key == 'angles' else msg.velocity
                for name, value in zip(msg.name, values):
                    run[key].setdefault(name, []).append((msg.header.stamp.to_sec(), value))
    if not run['planned'] or not run['driven']:
        raise RunError('%s: %d planned poses, %d odometry messages'
                       % (path, len(run['planned']), len(run['driven'])))
    return run


def pose_tuple(pose):
    p, q = pose.position, pose.orientation
    return (p.x, p.y, p.z, (q.x, q.y, q.z, q.w))


def plot(run, out, title):
    end = run['planned'][-1]
    t = [d[0] for d in run['driven']]
    distance = [math.dist(d[1:3], end[0:2]) for d in run['driven']]
    attitude = [attitude_angle(d[4], end[3]) for d in run['driven']]
    fig, ax = plt.subplots(2, 2, figsize=(12, 9))
    a = ax[0][0]
    a.plot([p[0] for p in run['planned']], [p[1] for p in run['planned']], 'g', linewidth=5,
           alpha=0.4, label='planned')
    a.plot([d[1] for d in run['driven']], [d[2] for d in run['driven']], 'b', label='driven')
    a.plot([0.0], [0.0], 'ko', label='start')
    a.plot([end[0]], [end[1]], 'r*', markersize=12, label='plan end')
    a.set_xlabel('X [m]'); a.set_ylabel('Y [m]'); a.set_aspect('equal', 'datalim')
    a.set_title('centre on the plane'); a.legend(loc='best')
    a = ax[0][1]
    a.semilogy(t, [max(d, 1e-9) for d in distance], 'b', label='|centre - plan end| [m]')
    a.semilogy(t, [max(d, 1e-9) for d in attitude], 'r', label='attitude to plan end [rad]')
    a.set_xlabel('t [s]'); a.set_title('distance to the plan\'s end'); a.legend(loc='best')
    a = ax[1][0]
    for (name, series), colour in zip(sorted(run['measured'].items()), 'br'):
        a.plot([s[0] for s in series], [s[1] for s in series], colour, label=name + ' measured')
    for (name, series), colour in zip(sorted(run['command'].items()), 'br'):
        a.plot([s[0] for s in series], [s[1] for s in series], colour + ':', label=name + ' set-point')
    a.set_xlabel('t [s]'); a.set_ylabel('[rad/s]'); a.set_title('rotor speeds (eq 11)')
    a.legend(loc='best')
    a = ax[1][1]
    for (name, series), colour in zip(sorted(run['angles'].items()), 'br'):
        a.plot([s[0] for s in series], [s[1] for s in series], colour, label=name)
    a.set_xlabel('t [s]'); a.set_ylabel('[rad]'); a.set_title('rotor angles'); a.legend(loc='best')
    for row in ax:
        for a in row:
            a.grid(True, alpha=0.3)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=80)
    return distance[-1], attitude[-1], t[-1]


def main():
    args = run_figure_arguments(__doc__, '/rotor')
    run = read_or_exit(read_bag, args)
    distance, attitude, t_end = plot(run, args.out, args.title)
    print('wrote %s; at t = %.2f s the centre is %.3g m and the attitude %.3g rad from the plan\'s '
          'end' % (args.out, t_end, distance, attitude))


if __name__ == '__main__':
    main()
