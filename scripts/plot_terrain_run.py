#!/usr/bin/env python3
"""Plot a terrain run (a recorded stack's bag or a `sphere_sim terrain` CSV) and print its summary.

    plot_terrain_run.py RUN --out PNG [--paper PNG] [--ns /sphere] [--threshold 0.1]
                        [--steady-from 40] [--config DIR]

RUN is a bag (any file not ending in .csv) or a CSV written by `sphere_sim terrain --out`.
Python with Debian's matplotlib, not C++: rosbag's Python API reads bags (message classes rebuilt
from the bag, no sourced workspace needed), matplotlib draws 3D axes, and plotting is no hot path.

--out: two panels, the XY path driven against the desired path and |e_t| over time with the
threshold line. --paper: the terrain paper's figures for the run in one PNG: the 3D trajectory of
the contact point on the terrain against the desired path, X, Y and Z against time (driven and
desired), |e_t|, the drive rates (realised; from a bag also the commanded set-points), and the
heading psi with the RS tilt phi. The terrain is drawn from config/terrain.yaml (--config DIR
holds config/; by default the package's own).

From a bag, with the rosbag Python API:
  <ns>/tracking_error     spherical_robots/TrackingError  (error_norm = |e_t|, desired = p_d)
  <ns>/terrain_state      spherical_robots/TerrainState   (contact point P0, psi, phi, rates)
  <ns>/desired_path       nav_msgs/Path                   (the reference, usually latched)
  <ns>/actuators/command  sensor_msgs/JointState          (set-points; optional)
A topic missing under <ns> is looked up by its message type. From a CSV, the columns that
`sphere_sim terrain --help` lists (t, x0..z0, xd..zd, e_norm, psi, phi, *_rate).

Times are header stamps (or the CSV's t) in simulated time, which starts at 0; a bag recorded in
wall time is measured from its first tracking-error message.

The summary counts the sign changes of the commanded rates from --steady-from on: consecutive
set-points of one actuator of opposite signs, both above 0.01 rad/s in magnitude (a rate that
chatters at convergence, docs/results.md). From a bag these are actuators/command's set-points;
a CSV holds none, so there they are the realised rates.

Exit status: 0 on success, 1 if the run cannot be read or holds no tracking errors or states.
"""
import argparse
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# The sibling module, also when a catkin devel-space relay runs this file (it sets __file__).
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from plot_support import (JOINT_STATE, PATH, TRACKING_ERROR, RunError, find_topic,  # noqa: E402
                          open_bag)

TERRAIN_STATE = "spherical_robots/TerrainState"
RATES = ("roll_rate", "lateral_rate", "turn_rate")
CSV_COLUMNS = ("t", "x0", "y0", "z0", "xd", "yd", "zd", "e_norm", "psi", "phi") + RATES


def new_run():
    """What a run holds, from either source. errors: [(t, |e_t|)]; desired: [(x, y, z)] at the
    same times; states: [(t, x, y, z, psi, phi, roll, lateral, turn)]; path: [(x, y, z)] or None;
    commands: {joint name: [(t, rate)]} (bags only)."""
    return {"errors": [], "desired": [], "states": [], "path": None, "commands": {},
            "robot": "?", "source": ""}


def read_bag(bag_path, ns):
    with open_bag(bag_path) as (bag, topics):
        error_topic = find_topic(topics, ns, "tracking_error", TRACKING_ERROR)
        state_topic = find_topic(topics, ns, "terrain_state", TERRAIN_STATE)
        path_topic = find_topic(topics, ns, "desired_path", PATH)
        wanted_command = ns.rstrip("/") + "/actuators/command"
        command_topic = wanted_command if topics.get(wanted_command) == JOINT_STATE else None
        if error_topic is None or state_topic is None:
            raise RunError("%s has no %s or no %s messages (topics: %s)"
                           % (bag_path, TRACKING_ERROR, TERRAIN_STATE,
                              ", ".join(sorted(topics)) or "none"))
        run = new_run()
        run["source"] = "bag"
        for topic, msg, bag_time in bag.read_messages(
                topics=[t for t in (error_topic, state_topic, path_topic, command_topic) if t]):
            stamp = msg.header.stamp.to_sec() or bag_time.to_sec()
            if topic == error_topic:
                run["errors"].append((stamp, msg.error_norm))
                run["desired"].append((msg.desired.x, msg.desired.y, msg.desired.z))
            elif topic == state_topic:
                c = msg.contact_point
                run["states"].append((stamp, c.x, c.y, c.z, msg.psi, msg.phi, msg.roll_rate,
                                      msg.lateral_rate, msg.turn_rate))
                run["robot"] = "%s, %s model" % (msg.robot_type, msg.contact_model)
            elif topic == command_topic:
                for name, rate in zip(msg.name, msg.velocity):
                    run["commands"].setdefault(name, []).append((stamp, rate))
            else:
                run["path"] = [(p.pose.position.x, p.pose.position.y, p.pose.position.z)
                               for p in msg.poses]
    if not run["errors"] or not run["states"]:
        raise RunError("%s: %d tracking-error and %d terrain-state messages"
                       % (bag_path, len(run["errors"]), len(run["states"])))
    # Simulated time starts at 0; a bag recorded in wall time is measured from its first error.
    first = run["errors"][0][0]
    if first >= 1e6:
        run["errors"] = [(t - first, e) for t, e in run["errors"]]
        run["states"] = [(s[0] - first,) + s[1:] for s in run["states"]]
        run["commands"] = {n: [(t - first, r) for t, r in v] for n, v in run["commands"].items()}
    return run


def read_csv(csv_path, robot=None):
    try:
        with open(csv_path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as exc:
        raise RunError("cannot read %s: %s" % (csv_path, exc))
    if not rows:
        raise RunError("%s has no rows" % csv_path)
    missing = [c for c in CSV_COLUMNS if c not in rows[0]]
    if missing:
        raise RunError("%s is not a sphere_sim terrain CSV (no column %s)"
                       % (csv_path, ", ".join(missing)))
    try:
        data = [{c: float(r[c]) for c in CSV_COLUMNS} for r in rows]
    except (TypeError, ValueError) as exc:
        raise RunError("%s: a cell is not a number: %s" % (csv_path, exc))
    run = new_run()
    run["source"] = "csv"
    run["robot"] = robot or "sphere_sim"
    for r in data:
        run["errors"].append((r["t"], r["e_norm"]))
        run["desired"].append((r["xd"], r["yd"], r["zd"]))
        run["states"].append((r["t"], r["x0"], r["y0"], r["z0"], r["psi"], r["phi"])
                             + tuple(r[k] for k in RATES))
    return run


def read_run(path, ns):
    """A run from a bag or, for a file ending in .csv, from a sphere_sim terrain CSV."""
    if path.lower().endswith(".csv"):
        return read_csv(path)
    return read_bag(path, ns)


def summarise(errors, threshold, steady_from):
    """Times relative to the start of the simulation; the first time under threshold;
    mean and max |e_t| from steady_from on."""
    first = errors[0][0]
    t0 = 0.0 if first < 1e6 else first  # simulated time starts at 0; wall time does not
    times = [t - t0 for t, _ in errors]
    norms = [e for _, e in errors]
    reached = next((t for t, e in zip(times, norms) if e < threshold), None)
    steady = [e for t, e in zip(times, norms) if t >= steady_from]
    return {
        "times": times, "norms": norms, "reached": reached,
        "steady_mean": sum(steady) / len(steady) if steady else math.nan,
        "steady_max": max(steady) if steady else math.nan,
        "steady_n": len(steady),
    }


SIGN_FLOOR = 0.01  # [rad/s]: a sign change counts when both neighbours are above it


def sign_changes(series, steady_from, floor=SIGN_FLOOR):
    """series: {name: [(t, rate)]} in time order. The sign changes from steady_from on (pairs of
    consecutive samples of one series with opposite signs, both above floor in magnitude) and the
    number of such pairs looked at, summed over the series: (changes, pairs)."""
    changes = pairs = 0
    for samples in series.values():
        for (_, before), (t, now) in zip(samples, samples[1:]):
            if t < steady_from:
                continue
            pairs += 1
            changes += before * now < 0.0 and abs(before) > floor and abs(now) > floor
    return changes, pairs


def commanded_rates(run):
    """The set-points of a bag, or a CSV's realised rates, as {name: [(t, rate)]}, and what they
    are."""
    if run["commands"]:
        return run["commands"], "commanded set-points"
    rates = {key: [(s[0], s[6 + i]) for s in run["states"]] for i, key in enumerate(RATES)}
    return {k: v for k, v in rates.items() if any(r != 0.0 for _, r in v)}, "realised rates"


def column(rows, i):
    return [r[i] for r in rows]


def desired_reference(run):
    """The desired path as (label, [(x, y, z)]): the published path, else the desired points."""
    if run["path"]:
        return "desired path", run["path"]
    return "desired point p_d", run["desired"]


def draw_xy(ax, run):
    label, desired = desired_reference(run)
    ax.plot(column(desired, 0), column(desired, 1), "k--", lw=1.2, label=label)
    xs, ys = column(run["states"], 1), column(run["states"], 2)
    ax.plot(xs, ys, "C0-", lw=1.5, label="driven (contact point P0)")
    ax.plot(xs[0], ys[0], "go", label="first sample")
    ax.plot(xs[-1], ys[-1], "rs", label="last sample")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    ax.set_title("XY path: driven vs desired")


def draw_error(ax, s, threshold, steady_from):
    floor = 1e-6  # log axis: an exact zero error is drawn at the floor
    ax.semilogy(s["times"], [max(e, floor) for e in s["norms"]], "C0-", lw=1.2, label="|e_t|")
    ax.axhline(threshold, color="r", ls="--", lw=1, label="%g m" % threshold)
    ax.axvline(steady_from, color="0.5", ls=":", lw=1, label="t = %g s" % steady_from)
    if s["reached"] is not None:
        ax.axvline(s["reached"], color="g", ls=":", lw=1,
                   label="|e_t| < %g m at %.2f s" % (threshold, s["reached"]))
    ax.set_xlabel("t [s] (simulated)")
    ax.set_ylabel("|e_t| [m]")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    ax.set_title("tracking error")


def plot(run, s, threshold, steady_from, out, title):
    fig, (ax_xy, ax_e) = plt.subplots(1, 2, figsize=(13, 5.5))
    draw_xy(ax_xy, run)
    draw_error(ax_e, s, threshold, steady_from)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def terrain_height(config_dir):
    """z = f(x, y) of config/terrain.yaml (eq 59 cosine, plane or tilted plane), or None."""
    import yaml
    candidates = [os.path.join(config_dir, "config", "terrain.yaml")] if config_dir else []
    here = os.path.dirname(os.path.abspath(__file__))
    candidates += [os.path.join(here, "..", "config", "terrain.yaml"),  # source tree
                   os.path.join(here, "..", "..", "share", "spherical_robots", "config",
                                "terrain.yaml")]  # installed: lib/spherical_robots/
    for path in candidates:
        if os.path.isfile(path):
            with open(path) as f:
                surface = yaml.safe_load(f)["terrain"]["surface"]
            kind = surface.get("type", "cosine")
            if kind == "cosine":
                a, w = float(surface["amplitude"]), float(surface["frequency"])
                return lambda x, y: a * (math.cos(w * x) + math.cos(w * y) - 2.0)
            off = float(surface.get("offset", 0.0))
            sx, sy = float(surface.get("slope_x", 0.0)), float(surface.get("slope_y", 0.0))
            return lambda x, y: off + sx * x + sy * y
    return None


def plot_paper(run, s, threshold, steady_from, out, title, height):
    """The terrain paper's figures for one run, in one PNG (2 x 3 panels)."""
    import numpy as np
    fig = plt.figure(figsize=(18, 10))
    states = run["states"]
    t = column(states, 0)
    x, y, z = column(states, 1), column(states, 2), column(states, 3)
    label, desired = desired_reference(run)

    ax3 = fig.add_subplot(2, 3, 1, projection="3d")
    if height is not None:
        xs_all, ys_all = x + column(desired, 0), y + column(desired, 1)
        margin = 0.5
        gx = np.linspace(min(xs_all) - margin, max(xs_all) + margin, 60)
        gy = np.linspace(min(ys_all) - margin, max(ys_all) + margin, 60)
        mx, my = np.meshgrid(gx, gy)
        mz = np.vectorize(height)(mx, my)
        ax3.plot_surface(mx, my, mz, cmap="summer", alpha=0.35, linewidth=0, antialiased=True)
    ax3.plot(column(desired, 0), column(desired, 1), column(desired, 2), "k--", lw=1.2,
             label=label)
    ax3.plot(x, y, z, "C0-", lw=1.6, label="driven P0")
    ax3.scatter([x[0]], [y[0]], [z[0]], color="g", s=25, label="start")
    ax3.set_xlabel("x [m]")
    ax3.set_ylabel("y [m]")
    ax3.set_zlabel("z [m]")
    ax3.view_init(elev=35, azim=-60)
    ax3.legend(loc="upper left", fontsize=8)
    ax3.set_title("trajectory on the terrain")

    ax = fig.add_subplot(2, 3, 2)
    te = s["times"]
    for i, (name, colour) in enumerate((("X", "C0"), ("Y", "C1"), ("Z", "C2"))):
        ax.plot(t, column(states, 1 + i), color=colour, lw=1.3, label=name + " (P0)")
        ax.plot(te, column(run["desired"], i), color=colour, ls="--", lw=1, label=name + "_d")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("[m]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8, ncol=3)
    ax.set_title("position vs time: driven (solid), desired (dashed)")

    draw_error(fig.add_subplot(2, 3, 3), s, threshold, steady_from)

    ax = fig.add_subplot(2, 3, 4)
    draw_xy(ax, run)

    ax = fig.add_subplot(2, 3, 5)
    names = {"roll_rate": "roll (θ̇ / α̇)", "lateral_rate": "lateral (φ̇; RS tilt rate)",
             "turn_rate": "turn (ψ̇)"}
    for i, key in enumerate(RATES):
        values = column(states, 6 + i)
        if any(abs(v) > 0.0 for v in values):
            ax.plot(t, values, color="C%d" % i, lw=1.1, label="realised " + names[key])
    for j, (joint, samples) in enumerate(sorted(run["commands"].items())):
        ax.plot(column(samples, 0), column(samples, 1), color="C%d" % (3 + j), lw=0.6, alpha=0.6,
                ls=":", label="commanded %s" % joint)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("rate [rad/s]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    ax.set_title("control signals: drive rates")

    ax = fig.add_subplot(2, 3, 6)
    ax.plot(t, column(states, 4), "C0-", lw=1.2, label="heading ψ")
    phi = column(states, 5)
    if any(abs(v) > 0.0 for v in phi):
        ax.plot(t, phi, "C3-", lw=1.2, label="RS tilt φ")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("[rad]")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    ax.set_title("heading and tilt")

    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run", metavar="RUN",
                        help="recorded bag of a terrain stack, or a sphere_sim terrain CSV")
    parser.add_argument("--out", required=True, help="PNG file to write (XY path and |e_t|)")
    parser.add_argument("--paper", help="PNG file for the paper-style figures (optional)")
    parser.add_argument("--ns", default="/sphere", help="namespace of the stack's topics (bags)")
    parser.add_argument("--threshold", type=float, default=0.1, help="|e_t| threshold [m]")
    parser.add_argument("--steady-from", type=float, default=40.0,
                        help="start of the steady-state window [s]")
    parser.add_argument("--config", help="directory holding config/terrain.yaml (--paper's terrain)")
    args = parser.parse_args(argv)

    run_path, out = os.path.abspath(args.run), os.path.abspath(args.out)
    try:
        run = read_run(run_path, args.ns)
    except RunError as exc:
        print("plot_terrain_run: %s" % exc, file=sys.stderr)
        return 1
    s = summarise(run["errors"], args.threshold, args.steady_from)
    title = "%s  (%s)" % (os.path.basename(run_path), run["robot"])
    os.makedirs(os.path.dirname(out), exist_ok=True)
    plot(run, s, args.threshold, args.steady_from, out, title)
    paper = os.path.abspath(args.paper) if args.paper else None
    if paper:
        os.makedirs(os.path.dirname(paper), exist_ok=True)
        plot_paper(run, s, args.threshold, args.steady_from, paper, title,
                   terrain_height(args.config))

    reached = ("t = %.2f s" % s["reached"]) if s["reached"] is not None else "never"
    path_text = ("%d poses" % len(run["path"])) if run["path"] else "none in the %s" % run["source"]
    steady = ("mean %.3g m, max %.3g m (%d samples)"
              % (s["steady_mean"], s["steady_max"], s["steady_n"])) if s["steady_n"] else "no samples"
    series, what = commanded_rates(run)
    changes, pairs = sign_changes(series, args.steady_from)
    rows = [
        ("samples", "%d tracking errors (t = %.2f .. %.2f s), %d terrain states, desired path %s"
         % (len(s["norms"]), s["times"][0], s["times"][-1], len(run["states"]), path_text)),
        ("|e_t| < %g m first" % args.threshold, reached),
        ("|e_t| for t >= %g s" % args.steady_from, steady),
        ("sign changes", "%d of %d steps of the %s for t >= %g s (%s)"
         % (changes, pairs, what, args.steady_from, ", ".join(sorted(series)))),
        (run["source"], run_path),
        ("plot", out),
    ]
    if paper:
        rows.append(("paper figures", paper))
    print("terrain run (%s)" % run["robot"])
    for label, text in rows:
        print("  %-22s %s" % (label + ":", text))
    if s["times"][0] > 0.5:
        print("  note: the %s starts at t = %.2f s; the run before that was not recorded"
              % (run["source"], s["times"][0]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
