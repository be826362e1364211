#!/usr/bin/python3
"""A FreeBOT chain's run (Zong et al. 2022) from a recorded FreeBOT stack's bag: the end-effector's
path in 3D with the goals, its position and orientation error to the goal in force over time
with each goal's verdicts, the joint variables of every SRC joint (trolley heading phi_i, the
rotation angles of q_{i,1} and q_{i-1,2}) and the wheel rates (measured; set-points dotted).

usage: plot_freebot_run.py BAG OUT.png [TITLE] [--ns /freebot]
e.g.   roslaunch spherical_robots freebot_stack.launch duration:=28 record:=/tmp/freebot.bag
       /usr/bin/python3 scripts/plot_freebot_run.py /tmp/freebot.bag /tmp/freebot.png

Topics under <ns> (a topic missing there is looked up by its message type): freebot_state (the
chain, as the plant integrates it from the measured wheel rates), ik_target (each goal freebot_ik
took, stamped when it took it), move_freebot/result (the move_freebot action's results: each
goal's verdict), actuators/command and actuators/state. Prints each goal's verdict.
"""
import math
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

# The sibling module, also when a catkin devel-space relay runs this file (it sets __file__).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from plot_support import (JOINT_STATE, RunError, attitude_angle, find_topic,  # noqa: E402
                          open_bag, read_or_exit, run_figure_arguments)

FREEBOT_STATE = 'spherical_robots/FreebotState'
ACTION_RESULT = 'spherical_robots/MoveFreebotActionResult'
POSE_STAMPED = 'geometry_msgs/PoseStamped'
VERDICTS = {1: 'ARRIVED', 2: 'UNREACHABLE', 3: 'REJECTED', 4: 'PREEMPTED', 5: 'ABORTED'}
ARRIVED = 1


def quaternion(q):
    return (q.x, q.y, q.z, q.w)


def rotation_angle(q):
    """Angle [rad] of the rotation a unit quaternion (x, y, z, w) makes."""
    return attitude_angle(q, (0.0, 0.0, 0.0, 1.0))


def read_bag(path, ns):
    run = {'states': [], 'goals': [], 'results': [], 'command': {}, 'measured': {}}
    with open_bag(path) as (bag, topics):
        names = {
            'states': find_topic(topics, ns, 'freebot_state', FREEBOT_STATE),
            'goals': find_topic(topics, ns, 'ik_target', POSE_STAMPED),
            'results': find_topic(topics, ns, 'move_freebot/result', ACTION_RESULT),
            'command': ns.rstrip('/') + '/actuators/command',
            'measured': ns.rstrip('/') + '/actuators/state'}
        if names['states'] is None:
            raise RunError('%s has no %s (topics: %s)'
                           % (path, FREEBOT_STATE, ', '.join(sorted(topics)) or 'none'))
        kind = {topic: key for key, topic in names.items() if topic}
        for topic, msg, bag_time in bag.read_messages(
                topics=sorted(t for t in kind if t in topics)):
            # Older bags' ik_target echoed the goal's stamp, often 0 for one typed by hand: it took
            # effect when it was received.
            key, stamp = kind[topic], msg.header.stamp.to_sec() or bag_time.to_sec()
            if key == 'states':
                e = msg.end_effector
                run['states'].append({
                    't': stamp, 'position': (e.position.x, e.position.y, e.position.z),
                    'orientation': quaternion(e.orientation), 'heading': list(msg.heading),
                    'link': [rotation_angle(quaternion(q)) for q in msg.link],
                    'base': [rotation_angle(quaternion(q)) for q in msg.base]})
            elif key == 'goals':
                p = msg.pose.position
                run['goals'].append((stamp, (p.x, p.y, p.z), quaternion(msg.pose.orientation)))
            elif key == 'results':
                r = msg.result
                run['results'].append((stamp, r.status, r.position_error, r.orientation_error,
                                       r.elapsed, r.message))
            elif topics[topic] == JOINT_STATE:
                for name, rate in zip(msg.name, msg.velocity):
                    run[key].setdefault(name, []).append((stamp, rate))
    if not run['states']:
        raise RunError('%s: no %s messages' % (path, FREEBOT_STATE))
    return run


def goal_errors(run):
    """(t, position error [m], orientation error [rad]) to the latest goal, from the first goal on.
    A goal with the zero quaternion asks for a position only: no orientation error."""
    errors, goals = [], iter(run['goals'])
    goal, upcoming = None, next(goals, None)
    for s in run['states']:
        while upcoming is not None and upcoming[0] <= s['t']:
            goal, upcoming = upcoming, next(goals, None)
        if goal is None:
            continue
        orientation = (attitude_angle(s['orientation'], goal[2])
                       if any(goal[2]) else float('nan'))
        errors.append((s['t'], math.dist(s['position'], goal[1]), orientation))
    return errors


def plot(run, out, title):
    t = [s['t'] for s in run['states']]
    modules = len(run['states'][0]['heading'])
    colours = plt.rcParams['axes.prop_cycle'].by_key()['color']
    fig = plt.figure(figsize=(16, 9))
    a = fig.add_subplot(2, 3, 1, projection='3d')
    a.plot(*zip(*[s['position'] for s in run['states']]), 'b', label='end-effector')
    for i, (_, p, _) in enumerate(run['goals']):
        a.scatter(*p, color='r', marker='*', s=120, label='goals' if i == 0 else None)
    a.scatter(0.0, 0.0, 0.0, color='k', s=40, label='base sphere centre')
    a.set_xlabel('X [m]'); a.set_ylabel('Y [m]'); a.set_zlabel('Z [m]')
    a.set_title('end-effector path'); a.legend(loc='best')
    a = fig.add_subplot(2, 3, 2)
    errors = goal_errors(run)
    if errors:
        a.semilogy([e[0] for e in errors], [max(e[1], 1e-9) for e in errors], 'b',
                   label='position [m]')
        a.semilogy([e[0] for e in errors], [max(e[2], 1e-9) for e in errors], 'r',
                   label='orientation [rad]')
    for stamp, status, *_ in run['results']:
        a.axvline(stamp, color='g' if status == ARRIVED else 'k', linestyle=':')
    a.set_xlabel('t [s]'); a.set_title('error to the goal (dotted: verdicts)')
    a.legend(loc='best')
    a = fig.add_subplot(2, 3, 3)
    for i in range(modules):
        a.plot(t, [s['heading'][i] for s in run['states']], color=colours[i % len(colours)],
               label='phi_%d' % (i + 1))
    a.set_xlabel('t [s]'); a.set_ylabel('[rad]'); a.set_title('trolley headings')
    a.legend(loc='best')
    a = fig.add_subplot(2, 3, 4)
    for i in range(modules):
        colour = colours[i % len(colours)]
        a.plot(t, [s['link'][i] for s in run['states']], color=colour,
               label='|q_%d,1|' % (i + 1))
        a.plot(t, [s['base'][i] for s in run['states']], color=colour, linestyle='--',
               label='|q_%d,2|' % i)
    a.set_xlabel('t [s]'); a.set_ylabel('[rad]'); a.set_title('joint rotation angles')
    a.legend(loc='best', ncol=2, fontsize='small')
    a = fig.add_subplot(2, 3, 5)
    for i, name in enumerate(sorted(run['measured'])):
        colour = colours[i % len(colours)]
        a.plot(*zip(*run['measured'][name]), color=colour, label=name)
        if name in run['command']:
            a.plot(*zip(*run['command'][name]), color=colour, linestyle=':')
    a.set_xlabel('t [s]'); a.set_ylabel('[rad/s]'); a.set_title('wheel rates')
    a.legend(loc='best', ncol=2, fontsize='x-small')
    a = fig.add_subplot(2, 3, 6)
    a.axis('off')
    a.text(0.0, 1.0, '\n'.join(verdict_lines(run)), va='top', family='monospace',
           fontsize='small')
    for a in fig.axes:
        if a.name != '3d':
            a.grid(True, alpha=0.3)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=80)


def verdict_lines(run):
    lines = ['goal verdicts']
    for stamp, status, position_error, orientation_error, elapsed, _ in run['results']:
        lines.append('t %6.2f s  %-11s  %.2e m  %.2e rad  after %.2f s'
                     % (stamp, VERDICTS.get(status, status), position_error, orientation_error,
                        elapsed))
    return lines


def main():
    args = run_figure_arguments(__doc__, '/freebot')
    run = read_or_exit(read_bag, args)
    plot(run, args.out, args.title)
    print('\n'.join(verdict_lines(run)))
    print('wrote %s' % args.out)


if __name__ == '__main__':
    main()
