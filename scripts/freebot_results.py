#!/usr/bin/env python3
"""Solves the FreeBOT paper's targets A, B, C (Zong et al. 2022, Table II; l_i = 0.034 m) with
`sphere_sim freebot-ik` for 3 and 4 joints, puts the joint states back through
`sphere_sim freebot-fk`, prints the table of docs/results.md and draws the chains
(docs/figures/freebot_targets.png).

usage: freebot_results.py SPHERE_SIM [--out-dir docs]
"""
import argparse
import json
import math
import os
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

RADIUS = 0.034
# Table II; the printed quaternions are unit only to 4 digits and are normalised here.
TARGETS = {
    "A": ([0.0036, 0.1636, 0.0924], [0.8610, 0.4687, 0.1356, 0.1437]),
    "B": ([0.1151, 0.1489, 0.0291], [0.8520, 0.3289, 0.2300, 0.3362]),
    "C": ([0.0924, 0.1597, 0.1154], [0.9682, 0.0874, 0.2220, 0.0756]),
}


def normalised(q):
    n = math.sqrt(sum(c * c for c in q))
    return [c / n for c in q]


def rotation(q):
    w, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


def solve(sim, work, joints, target):
    radii = ",".join([str(RADIUS)] * (joints + 1))
    position, orientation = target
    ik = os.path.join(work, "ik.json")
    values = position + normalised(orientation)
    status = subprocess.run([sim, "freebot-ik", "--radii", radii, "--target",
                             ",".join(repr(v) for v in values), "--out", ik],
                            stdout=subprocess.DEVNULL).returncode
    if status not in (0, 3):
        raise SystemExit(f"freebot-ik failed with exit status {status}")
    result = json.load(open(ik))
    fk = os.path.join(work, "fk.json")
    states = ";".join(",".join(repr(c) for c in pair) for pair in result["joint_quaternions"])
    subprocess.run([sim, "freebot-fk", "--radii", radii, "--joint-quaternions", states,
                    "--out", fk], check=True, stdout=subprocess.DEVNULL)
    return result, json.load(open(fk))["links"]


def draw_sphere(ax, centre, radius, colour):
    u, v = np.mgrid[0:2 * np.pi:16j, 0:np.pi:9j]
    ax.plot_wireframe(centre[0] + radius * np.cos(u) * np.sin(v),
                      centre[1] + radius * np.sin(u) * np.sin(v),
                      centre[2] + radius * np.cos(v), color=colour, linewidth=0.4)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sim")
    parser.add_argument("--out-dir", default="docs")
    args = parser.parse_args()
    fig = plt.figure(figsize=(15, 5.5))
    print("| target | joints | success | position error | orientation error |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for column, (name, target) in enumerate(TARGETS.items()):
            ax = fig.add_subplot(1, 3, column + 1, projection="3d")
            for joints, colour in ((3, "tab:red"), (4, "tab:blue")):
                result, links = solve(args.sim, work, joints, target)
                print(f"| {name} | {joints} | {result['success']} | "
                      f"{result['position_error'] * 1e3:.4g} mm | "
                      f"{result['orientation_error_deg']:.3g} deg |")
                centres = [np.zeros(3)] + [np.array(link["position"]) for link in links]
                ax.plot(*np.array(centres).T, "o-", color=colour,
                        label=f"{joints} joints: {'reached' if result['success'] else 'closest'}")
                for centre in centres:
                    draw_sphere(ax, centre, RADIUS, colour)
            position = np.array(target[0])
            frame = rotation(normalised(target[1]))
            for axis, colour in zip(range(3), ("r", "g", "b")):
                ax.quiver(*position, *(0.06 * frame[:, axis]), color=colour, linewidth=2)
            ax.set_title(f"target {name}")
            ax.set_xlim(-0.1, 0.2)
            ax.set_ylim(-0.05, 0.25)
            ax.set_zlim(-0.05, 0.25)
            ax.set_box_aspect((1, 1, 1))
            ax.set_xlabel("x [m]")
            ax.set_ylabel("y [m]")
            ax.set_zlabel("z [m]")
            ax.legend(loc="upper left", fontsize=8)
    os.makedirs(os.path.join(args.out_dir, "figures"), exist_ok=True)
    out = os.path.join(args.out_dir, "figures", "freebot_targets.png")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
