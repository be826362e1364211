#!/usr/bin/env python3
"""Runs `sphere_sim terrain` for every robot x path x contact model and writes the figures and
the table of docs/results.md (tracking figures and the paper-vs-rolling comparison).

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


def run(sim, config, robot, path, model, work):
    out = os.path.join(work, f"{robot}_{path}_{model}.csv")
    cmd = [sim, "terrain", "--robot", robot, "--path", path, "--model", model, "--out", out]
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


if __name__ == "__main__":
    main()
