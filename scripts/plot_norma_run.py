#!/usr/bin/python3
"""Figs 6-10 of Moazami et al. 2019 (Norma) from a `sphere_sim norma` closed-loop CSV or from a
recorded Norma stack's bag, plus the tracking error: XY path (Fig 6), X and Y against time
(Fig 7), T and F (Fig 8), the tilt phi (Fig 9), the slider delta (Fig 10) and |e|.

usage: plot_norma_run.py RUN OUT.png [TITLE] [--ns /norma]
RUN: a CSV (its name ends in .csv) or a bag (launch/record.launch, or norma_stack.launch record:=).
e.g.   sphere_sim norma --controller paper --out /tmp/paper.csv
       /usr/bin/python3 scripts/plot_norma_run.py /tmp/paper.csv docs/figures/norma_paper.png
       roslaunch spherical_robots norma_stack.launch duration:=60 record:=/tmp/norma.bag
       /usr/bin/python3 scripts/plot_norma_run.py /tmp/norma.bag /tmp/norma.png

From a bag: <ns>/norma_state (q, X, Y, the efforts T, F the plant integrated with; 1 kHz, read at
every 10th message) and <ns>/tracking_error (the desired point and |e|, as the controller saw
them). A topic missing under <ns> is looked up by its message type.
"""
import csv
import os
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

# The sibling module, also when a catkin devel-space relay runs this file (it sets __file__).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from plot_support import (TRACKING_ERROR, RunError, find_topic, open_bag,  # noqa: E402
                          read_or_exit, run_figure_arguments)

NORMA_STATE = 'spherical_robots/NormaState'
COLUMNS = ('t', 'X', 'Y', 'Xd', 'Yd', 'err', 'T', 'F', 'phi', 'delta')
STATE_STRIDE = 10  # norma_state comes at the plant's 1 kHz; 100 Hz draws the same curves


def read_csv(path):
    rows = list(csv.DictReader(open(path)))
    if not rows or any(c not in rows[0] for c in COLUMNS):
        raise RunError('%s is not a closed-loop sphere_sim norma CSV (columns %s)'
                       % (path, ', '.join(COLUMNS)))
    return {k: [float(r[k]) for r in rows] for k in COLUMNS}


def read_bag(path, ns):
    """The figure's columns from a bag: the state at STATE_STRIDE, each with the latest desired
    point and |e| published before it."""
    col = {k: [] for k in COLUMNS}
    with open_bag(path) as (bag, topics):
        state_topic = find_topic(topics, ns, 'norma_state', NORMA_STATE)
        error_topic = find_topic(topics, ns, 'tracking_error', TRACKING_ERROR)
        if state_topic is None or error_topic is None:
            raise RunError('%s has no %s or no %s messages (topics: %s)' % (
                path, NORMA_STATE, TRACKING_ERROR, ', '.join(sorted(topics)) or 'none'))
        error, count = None, 0
        for topic, msg, _ in bag.read_messages(topics=[state_topic, error_topic]):
            if topic == error_topic:
                error = msg
                continue
            count += 1
            if error is None or count % STATE_STRIDE:
                continue
            for key, value in zip(COLUMNS, (
                    msg.header.stamp.to_sec(), msg.x, msg.y, error.desired.x, error.desired.y,
                    error.error_norm, msg.torque, msg.force, msg.q[2], msg.q[3])):
                col[key].append(value)
    if not col['t']:
        raise RunError('%s: no %s after the first %s' % (path, NORMA_STATE, TRACKING_ERROR))
    return col


def read_run(path, ns):
    return read_csv(path) if path.lower().endswith('.csv') else read_bag(path, ns)


def main():
    args = run_figure_arguments(__doc__, '/norma')
    col = read_or_exit(read_run, args)
    t = col['t']
    fig, ax = plt.subplots(2, 3, figsize=(15, 8.5))
    a = ax[0][0]
    a.plot(col['Xd'], col['Yd'], 'k--', label='desired (eq 52)')
    a.plot(col['X'], col['Y'], 'b', label='robot')
    a.set_xlabel('X [m]'); a.set_ylabel('Y [m]'); a.set_aspect('equal', 'datalim')
    a.set_title('Fig. 6: XY trajectory'); a.legend(loc='best')
    a = ax[0][1]
    a.plot(t, col['Xd'], 'k--', label='X_d'); a.plot(t, col['X'], 'b', label='X')
    a.plot(t, col['Yd'], 'k:', label='Y_d'); a.plot(t, col['Y'], 'r', label='Y')
    a.set_xlabel('t [s]'); a.set_ylabel('[m]'); a.set_title('Fig. 7: X and Y'); a.legend(loc='best')
    a = ax[0][2]
    a.plot(t, col['err'], 'b')
    a.set_xlabel('t [s]'); a.set_ylabel('|e| [m]'); a.set_title('tracking error |e|')
    a = ax[1][0]
    a.plot(t, col['T'], 'b', label='T [N m]'); a.plot(t, col['F'], 'r', label='F [N]')
    a.set_xlabel('t [s]'); a.set_title('Fig. 8: control actions'); a.legend(loc='best')
    a = ax[1][1]
    a.plot(t, col['phi'], 'b')
    a.set_xlabel('t [s]'); a.set_ylabel('phi [rad]'); a.set_title('Fig. 9: tilt angle')
    a = ax[1][2]
    a.plot(t, col['delta'], 'b')
    a.set_xlabel('t [s]'); a.set_ylabel('delta [m]'); a.set_title('Fig. 10: slider displacement')
    for row in ax:
        for a in row:
            a.grid(True, alpha=0.3)
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.out, dpi=80)
    print('wrote %s (%d samples, t %.2f-%.2f s)' % (args.out, len(t), t[0], t[-1]))


if __name__ == '__main__':
    main()
