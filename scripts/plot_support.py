"""What the plotting tools (plot_terrain_run.py, plot_norma_run.py, plot_rotor_run.py,
plot_freebot_run.py) share: opening a bag and finding its topics, their command line for a run
and its figure, and the angle between two attitudes. A module beside them, not a program; each
tool puts its own directory on sys.path first, so this works from the source tree, the install
space and catkin's devel-space relays alike, with no workspace sourced (rosbag rebuilds the
message classes from the bag).
"""
import argparse
import contextlib
import math
import os
import sys

TRACKING_ERROR = "spherical_robots/TrackingError"
PATH = "nav_msgs/Path"
JOINT_STATE = "sensor_msgs/JointState"


class RunError(Exception):
    """A run that cannot be plotted: unreadable, or without the messages a figure needs."""


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


@contextlib.contextmanager
def open_bag(bag_path):
    """The bag, open, and its {topic: message type}; RunError if it cannot be read."""
    import rosbag  # only needed for bags
    try:
        bag = rosbag.Bag(bag_path)
    except Exception as exc:  # rosbag raises several types for unreadable bags
        raise RunError("cannot read %s: %s" % (bag_path, exc))
    with bag:
        yield bag, {t: i.msg_type for t, i in bag.get_type_and_topic_info().topics.items()}


def run_figure_arguments(doc, default_ns):
    """The command line RUN OUT.png [TITLE] [--ns NS] of a tool whose usage is its docstring."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("run", help="the recorded bag (or, where the tool reads one, a CSV)")
    parser.add_argument("out", help="the figure to write (PNG)")
    parser.add_argument("title", nargs="?", help="the figure's title")
    parser.add_argument("--ns", default=default_ns, help="the stack's namespace (%(default)s)")
    return parser.parse_args()


def read_or_exit(read, args):
    """read(args.run, args.ns), or exit with a one-line error naming the tool and the run."""
    try:
        return read(args.run, args.ns)
    except (OSError, RunError) as exc:
        sys.exit("%s: %s" % (os.path.basename(sys.argv[0]), exc))


def attitude_angle(q, r):
    """Angle [rad] of the rotation between two attitudes, quaternions (x, y, z, w) of any non-zero
    norm (a goal's may be unit only to a few digits): 2 atan2(|vector part|, |scalar part|) of
    q* r, accurate for small angles too, where acos of the dot product is not."""
    (x1, y1, z1, w1), (x2, y2, z2, w2) = q, r
    w = w1 * w2 + x1 * x2 + y1 * y2 + z1 * z2
    v = (w1 * x2 - x1 * w2 - y1 * z2 + z1 * y2, w1 * y2 - y1 * w2 - z1 * x2 + x1 * z2,
         w1 * z2 - z1 * w2 - x1 * y2 + y1 * x2)
    return 2.0 * math.atan2(math.hypot(*v), abs(w))
