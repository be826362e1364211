#!/usr/bin/env python3
"""Runs `sphere_sim terrain` for every robot x path x contact model and writes the figures and
the table of docs/results.md (tracking figures and the paper-vs-rolling comparison), and the
commanded rates of the paper's and the smooth law on the 3R circle, logged at every 5 ms step.

usage: terrain_results.py SPHERE_SIM [--config DIR] [--out-dir docs]
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROBOTS = ["3R", "2R", "RT", "RS"]
PATHS = ["circle", "diamond"]
MODELS = ["paper", "rolling"]
THRESHOLD, SETTLE = 0.1, 40.0


def run(sim, config, robot, path, model, work, law="paper", log_rate="10"):
    out = os.path.join(work, f"{robot}_{path}_{model}_{law}.csv")
    cmd = [sim, "terrain", "--robot", robot, "--path", path, "--model", model, "--law", law,
           "--log-rate", log_rate, "--out", out]
    if config:
        cmd += ["--config", config]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(out) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def summary(run_data):
    t, e = run_data["t"], run_data["e_norm"]
    first = next((ti for ti, ei in zip(t, e) if ei < THRESHOLD), float("nan"))
    after = [ei for ti, ei in zip(t, e) if ti >= SETTLE]
    return first, sum(after) / len(after), max(after)


def law_figure(sim, config, work, figures):
    """3R on the circle, paper model: the three commanded rates of each law (for 3R the realised
    rates are the commanded ones), over the run and over one second at every 5 ms step."""
    runs = {law: run(sim, config, "3R", "circle", "paper", work, law, "200")
            for law in ("paper", "smooth")}
    names = {"roll_rate": "roll θ̇", "lateral_rate": "lateral φ̇", "turn_rate": "turn ψ̇"}
    fig, axes = plt.subplots(2, 2, figsize=(15, 7.5), sharey="row")
    for col, (law, data) in enumerate(runs.items()):
        for row, (start, end) in enumerate(((0.0, 200.0), (100.0, 101.0))):
            ax = axes[row][col]
            keep = [i for i, t in enumerate(data["t"]) if start <= t <= end]
            for i, (key, label) in enumerate(names.items()):
                ax.plot([data["t"][k] for k in keep], [data[key][k] for k in keep], color="C%d" % i,
                        lw=0.8 if row == 0 else 1.0, marker="" if row == 0 else ".", ms=3,
                        label=label)
            ax.set_xlabel("t [s]")
            ax.set_ylabel("commanded rate [rad/s]")
            ax.grid(True, alpha=0.3)
            ax.set_title("%s law, %s" % (law, "whole run" if row == 0
                                         else "t = 100-101 s, every 5 ms step"))
        axes[0][col].legend(fontsize=8, loc="upper right")
    fig.suptitle("3R on the circle (eq 59 terrain, paper contact model): commanded drive rates")
    fig.tight_layout()
    name = os.path.join(figures, "terrain_laws_3R_circle.png")
    fig.savefig(name, dpi=90)
    print(f"wrote {name}", file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sphere_sim")
    parser.add_argument("--config", default="")
    parser.add_argument("--out-dir", default="docs")
    args = parser.parse_args()
    figures = os.path.join(args.out_dir, "figures")
    os.makedirs(figures, exist_ok=True)
    work = tempfile.mkdtemp()
    runs = {(r, p, m): run(args.sphere_sim, args.config, r, p, m, work)
            for r in ROBOTS for p in PATHS for m in MODELS}

    print("| robot | path | model | first \\|e_t\\| < 0.1 m [s] | mean \\|e_t\\| t ≥ 40 s [m] "
          "| max \\|e_t\\| t ≥ 40 s [m] |")
    print("|---|---|---|---|---|---|")
    for (robot, path, model), data in runs.items():
        first, mean, peak = summary(data)
        print(f"| {robot} | {path} | {model} | {first:.2f} | {mean:.4f} | {peak:.4f} |")

    for path in PATHS:
        fig, axes = plt.subplots(2, 4, figsize=(16, 7.5))
        for col, robot in enumerate(ROBOTS):
            xy, err = axes[0][col], axes[1][col]
            paper, rolling = runs[(robot, path, "paper")], runs[(robot, path, "rolling")]
            xy.plot(paper["xd"], paper["yd"], "k--", lw=1, label="desired")
            xy.plot(paper["x0"], paper["y0"], "C0", lw=1.2, label="paper model")
            xy.plot(rolling["x0"], rolling["y0"], "C3", lw=1.2, label="rolling model")
            xy.set_title(f"{robot}, {path}")
            xy.set_aspect("equal")
            xy.set_xlabel("x [m]")
            xy.set_ylabel("y [m]")
            err.semilogy(paper["t"], [max(e, 1e-6) for e in paper["e_norm"]], "C0", label="paper")
            err.semilogy(rolling["t"], [max(e, 1e-6) for e in rolling["e_norm"]], "C3",
                         label="rolling")
            err.axhline(THRESHOLD, color="gray", ls=":")
            err.set_xlabel("t [s]")
            err.set_ylabel("|e_t| [m]")
        axes[0][0].legend(fontsize=8)
        axes[1][0].legend(fontsize=8)
        fig.suptitle(f"Contact point P0 driven by the same pure-pursuit law: paper vs rolling "
                     f"contact model ({path})")
        fig.tight_layout()
        name = os.path.join(figures, f"terrain_contact_models_{path}.png")
        fig.savefig(name, dpi=90)
        print(f"wrote {name}", file=sys.stderr)
    law_figure(args.sphere_sim, args.config, work, figures)


if __name__ == "__main__":
    main()
