#!/usr/bin/python3
"""Figs 6-10 of Moazami et al. 2019 (Norma) from a `sphere_sim norma` closed-loop CSV, plus the
tracking error: XY path (Fig 6), X and Y against time (Fig 7), T and F (Fig 8), the tilt phi
(Fig 9), the slider delta (Fig 10) and |e|.

usage: plot_norma_run.py RUN.csv OUT.png [TITLE]
e.g.   sphere_sim norma --controller paper --out /tmp/paper.csv
       /usr/bin/python3 scripts/plot_norma_run.py /tmp/paper.csv docs/figures/norma_paper.png
"""
import csv
import sys

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    rows = list(csv.DictReader(open(sys.argv[1])))
    col = {k: [float(r[k]) for r in rows] for k in rows[0]}
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
    if len(sys.argv) == 4:
        fig.suptitle(sys.argv[3])
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=80)


if __name__ == '__main__':
    main()
