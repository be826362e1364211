#!/usr/bin/python3
"""Figures 9 and 10 of Svinin et al. (two-rotor sphere) from `sphere_sim rotor-step`:
the signed non-holonomic shift of the symmetric figure eight (a = b) against the inertia ratio k
for the section IV circle, and against the radius a for k = 2.5, with the published values marked.

The figure eight with a = b moves along the line at -eta_leaf/2 (eta_leaf = psi after the first
circle), so h is signed by the shift's component along that line; its zeros are the paper's k_i.

usage: /usr/bin/python3 scripts/rotor_figures.py SPHERE_SIM [OUT_DIR]   (default docs/figures)
"""
import json
import math
import os
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402

SIM = sys.argv[1]
OUT = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), '..', 'docs', 'figures')
ALPHA = 0.533680512  # geodesic radius of the k = 0, h = R circle (docs/errata.md S4)
A_SECTION_IV = math.sin(ALPHA)
TMP = os.path.join(tempfile.mkdtemp(prefix='rotor_figures.'), 'step.json')


def signed_shift(k, a):
    subprocess.run([SIM, 'rotor-step', '--k', repr(k), '--a', repr(a), '--b', repr(a), '--out', TMP],
                   check=True, stdout=subprocess.DEVNULL)
    step = json.load(open(TMP))
    axis = -0.5 * step['half']['psi']
    return step['full']['u'] * math.cos(axis) + step['full']['v'] * math.sin(axis)


def shift_vs_k():
    ks = [12.0 * i / 480 for i in range(481)]
    h = [signed_shift(k, A_SECTION_IV) for k in ks]
    fig, ax = plt.subplots(figsize=(7, 3.6))
    ax.plot(ks, h, 'b-', lw=1.2, label='signed h/R (ours)')
    ax.axhline(0.0, color='k', lw=0.6)
    for i, k in enumerate([0.233154, 2.64357, 5.20728, 7.80506, 10.9801]):
        ax.axvline(k, color='r', ls=':', lw=1.0, label='published $k_i$' if i == 0 else None)
    ax.plot([10.417091922], [0.0], 'go', label='our $k_5$ = 10.4171')
    ax.set_xlabel('inertia ratio k')
    ax.set_ylabel('h / R')
    ax.set_title('Fig. 9: shift of the figure eight, geodesic radius 0.533681 R')
    ax.legend(fontsize=8, loc='upper left')
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, 'rotor_shift_vs_k.png'), dpi=110)


def shift_vs_radius():
    radii = [0.02 + (0.699 - 0.02) * i / 400 for i in range(401)]
    h = [signed_shift(2.5, a) for a in radii]
    fig, ax = plt.subplots(figsize=(7, 3.6))
    ax.plot(radii, h, 'b-', lw=1.0, label='signed h/R, k = 2.5 (ours)')
    ax.axhline(1.0, color='k', lw=0.6)
    ax.axhline(-1.0, color='k', lw=0.6)
    for i, a in enumerate([0.300429, 0.491471, 0.538682, 0.609147]):
        ax.axvline(a, color='r', ls=':', lw=1.0, label='published $a_1 … a_4$' if i == 0 else None)
    ax.set_xlabel('Euclidean circle radius a / R')
    ax.set_ylabel('h / R')
    ax.set_title('Fig. 10: shift against the radius, k = 2.5; h/R = ±1 at the solutions')
    ax.legend(fontsize=8, loc='lower left')
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, 'rotor_shift_vs_radius.png'), dpi=110)


shift_vs_k()
shift_vs_radius()
os.remove(TMP)
os.rmdir(os.path.dirname(TMP))
