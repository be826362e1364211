#!/usr/bin/env python3
"""Plot a recorded terrain-stack run and print its tracking summary.

    plot_terrain_run.py BAG --out PNG [--ns /sphere] [--threshold 0.1] [--steady-from 40]

Reads, with the rosbag Python API,
  <ns>/tracking_error  spherical_robots/TrackingError  (error_norm = |e_t|, header stamp = t)
  <ns>/terrain_state   spherical_robots/TerrainState   (contact_point = P0, the path driven)
  <ns>/desired_path    nav_msgs/Path                   (the reference, usually latched)
and writes a PNG with two panels: the XY path driven against the desired path, and |e_t| over
time with the threshold line. A topic missing under <ns> is looked up by its message type.
rosbag rebuilds the message classes from the definitions stored in the bag, so the workspace
need not be sourced.

Times are the header stamps in simulated time, which starts at 0; a bag recorded in wall time
is measured from its first tracking-error message.

Exit status: 0 on success, 1 if the bag cannot be read or holds no tracking-error or
terrain-state messages.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import rosbag  # noqa: E402

TRACKING_ERROR = "spherical_robots/TrackingError"
TERRAIN_STATE = "spherical_robots/TerrainState"
PATH = "nav_msgs/Path"


class RunError(Exception):
    pass


def find_topic(topics, ns, name, msg_type):
    """The topic <ns>/<name> if the bag has it with msg_type, else the bag's only topic of msg_type."""
    wanted = ns.rstrip("/") + "/" + name
    if topics.get(wanted) == msg_type:
        return wanted
    candidates = sorted(t for t, ty in topics.items() if ty == msg_type)
    if len(candidates) == 1:
        return candidates[0]
    if candidates:
        raise RunError("no %s; several %s topics: %s (choose one with --ns)"
                       % (wanted, msg_type, ", ".join(candidates)))
    return None


def read_run(bag_path, ns):
    try:
        bag = rosbag.Bag(bag_path)
    except Exception as exc:  # rosbag raises several types for unreadable bags
        raise RunError("cannot read %s: %s" % (bag_path, exc))
    with bag:
        topics = {t: i.msg_type for t, i in bag.get_type_and_topic_info().topics.items()}
        error_topic = find_topic(topics, ns, "tracking_error", TRACKING_ERROR)
        state_topic = find_topic(topics, ns, "terrain_state", TERRAIN_STATE)
        path_topic = find_topic(topics, ns, "desired_path", PATH)
        if error_topic is None or state_topic is None:
            raise RunError("%s has no %s or no %s messages (topics: %s)"
                           % (bag_path, TRACKING_ERROR, TERRAIN_STATE,
                              ", ".join(sorted(topics)) or "none"))
        run = {"errors": [], "states": [], "path": None, "desired": []}
        for topic, msg, bag_time in bag.read_messages(
                topics=[t for t in (error_topic, state_topic, path_topic) if t]):
            if topic == error_topic:
                stamp = msg.header.stamp.to_sec() or bag_time.to_sec()
                run["errors"].append((stamp, msg.error_norm))
                run["desired"].append((msg.desired.x, msg.desired.y))
            elif topic == state_topic:
                run["states"].append((msg.contact_point.x, msg.contact_point.y))
                run["robot"] = "%s, %s model" % (msg.robot_type, msg.contact_model)
            else:
                run["path"] = [(p.pose.position.x, p.pose.position.y) for p in msg.poses]
    if not run["errors"] or not run["states"]:
        raise RunError("%s: %d tracking-error and %d terrain-state messages"
                       % (bag_path, len(run["errors"]), len(run["states"])))
    run["topics"] = (error_topic, state_topic, path_topic)
    return run


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


def plot(run, s, threshold, steady_from, out, title):
    fig, (ax_xy, ax_e) = plt.subplots(1, 2, figsize=(13, 5.5))
    desired = run["path"] if run["path"] else run["desired"]
    label = "desired path" if run["path"] else "desired point p_d"
    ax_xy.plot([p[0] for p in desired], [p[1] for p in desired], "k--", lw=1.2, label=label)
    xs, ys = [p[0] for p in run["states"]], [p[1] for p in run["states"]]
    ax_xy.plot(xs, ys, "C0-", lw=1.5, label="driven (contact point P0)")
    ax_xy.plot(xs[0], ys[0], "go", label="first sample")
    ax_xy.plot(xs[-1], ys[-1], "rs", label="last sample")
    ax_xy.set_xlabel("x [m]")
    ax_xy.set_ylabel("y [m]")
    ax_xy.set_aspect("equal", adjustable="datalim")
    ax_xy.grid(True, alpha=0.3)
    ax_xy.legend(loc="best", fontsize=8)
    ax_xy.set_title("XY path: driven vs desired")

    floor = 1e-6  # log axis: an exact zero error is drawn at the floor
    ax_e.semilogy(s["times"], [max(e, floor) for e in s["norms"]], "C0-", lw=1.2, label="|e_t|")
    ax_e.axhline(threshold, color="r", ls="--", lw=1, label="%g m" % threshold)
    ax_e.axvline(steady_from, color="0.5", ls=":", lw=1, label="t = %g s" % steady_from)
    if s["reached"] is not None:
        ax_e.axvline(s["reached"], color="g", ls=":", lw=1,
                     label="|e_t| < %g m at %.2f s" % (threshold, s["reached"]))
    ax_e.set_xlabel("t [s] (simulated)")
    ax_e.set_ylabel("|e_t| [m]")
    ax_e.grid(True, which="both", alpha=0.3)
    ax_e.legend(loc="best", fontsize=8)
    ax_e.set_title("tracking error")

    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("bag", help="recorded bag of a terrain stack")
    parser.add_argument("--out", required=True, help="PNG file to write")
    parser.add_argument("--ns", default="/sphere", help="namespace of the stack's topics")
    parser.add_argument("--threshold", type=float, default=0.1, help="|e_t| threshold [m]")
    parser.add_argument("--steady-from", type=float, default=40.0,
                        help="start of the steady-state window [s]")
    args = parser.parse_args(argv)

    bag_path, out = os.path.abspath(args.bag), os.path.abspath(args.out)
    try:
        run = read_run(bag_path, args.ns)
    except RunError as exc:
        print("plot_terrain_run: %s" % exc, file=sys.stderr)
        return 1
    s = summarise(run["errors"], args.threshold, args.steady_from)
    title = "%s  (%s)" % (os.path.basename(bag_path), run.get("robot", "?"))
    os.makedirs(os.path.dirname(out), exist_ok=True)
    plot(run, s, args.threshold, args.steady_from, out, title)

    reached = ("t = %.2f s" % s["reached"]) if s["reached"] is not None else "never"
    path_text = ("%d poses" % len(run["path"])) if run["path"] else "none in the bag"
    steady = ("mean %.4f m, max %.4f m (%d samples)"
              % (s["steady_mean"], s["steady_max"], s["steady_n"])) if s["steady_n"] else "no samples"
    rows = [
        ("samples", "%d tracking errors (t = %.2f .. %.2f s), %d terrain states, desired path %s"
         % (len(s["norms"]), s["times"][0], s["times"][-1], len(run["states"]), path_text)),
        ("|e_t| < %g m first" % args.threshold, reached),
        ("|e_t| for t >= %g s" % args.steady_from, steady),
        ("bag", bag_path),
        ("plot", out),
    ]
    print("terrain run (%s)" % run.get("robot", "?"))
    for label, text in rows:
        print("  %-22s %s" % (label + ":", text))
    if s["times"][0] > 0.5:
        print("  note: the bag starts at t = %.2f s; the run before that was not recorded"
              % s["times"][0])
    return 0


if __name__ == "__main__":
    sys.exit(main())
