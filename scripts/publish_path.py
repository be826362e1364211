#!/usr/bin/env python3
"""Publishes a path from a CSV file as a latched nav_msgs/Path, for pure_pursuit_controller.

    rosrun spherical_robots publish_path.py FILE.csv __ns:=sphere
    rosrun spherical_robots publish_path.py FILE.csv --topic /sphere/path --delay 5

FILE.csv holds rows t,x,y (a timed path: t [s] strictly increasing) or x,y (untimed: the controller
follows it at its ~untimed_speed), x and y [m] in --frame; a header row naming the columns is
optional, and empty lines and lines starting with # are skipped (the format of
`sphere_sim terrain --path-file`). A timed path's poses are stamped now + --delay + (t - first t),
so that the controller starts it at once, or --delay seconds from now; an untimed path's stamps are
all zero, as planners publish them. The controller interpolates either as sphere_sim does and
refuses a bad path on its log and /diagnostics, keeping the path it had (docs/nodes.md,
"pure_pursuit_controller"). The message stays latched until this node is stopped (Ctrl-C), so that a
controller started later receives it too.
"""
import argparse
import math
import sys

import rospy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path

# REP 105's fixed frame, shared by every stack on a master; pure_pursuit_controller transforms a
# path into its <prefix>odom through tf (a static map -> odom in each stack).
DEFAULT_FRAME = 'map'


def read_rows(path):
    """(columns, [(line number, [numbers])]): the file's rows, columns ('t', 'x', 'y') or ('x', 'y')."""
    columns, rows = None, []
    with open(path) as f:
        for number, line in enumerate(f, start=1):
            line = line.strip()
            if not line or line.startswith('#'):
                continue
            cells = [cell.strip() for cell in line.split(',')]
            try:
                values = [float(cell) for cell in cells]
            except ValueError:
                if columns is None and cells in (['t', 'x', 'y'], ['x', 'y']):
                    columns = tuple(cells)
                    continue
                raise ValueError('%s line %d: %r is neither a header (t,x,y or x,y) nor a row of '
                                 'numbers' % (path, number, line))
            if columns is None:
                if len(cells) not in (2, 3):
                    raise ValueError('%s line %d: %d cells; a row is t,x,y or x,y'
                                     % (path, number, len(cells)))
                columns = ('t', 'x', 'y') if len(cells) == 3 else ('x', 'y')
            if len(values) != len(columns):
                raise ValueError('%s line %d: %d cells, expected %d (%s)'
                                 % (path, number, len(values), len(columns), ','.join(columns)))
            rows.append((number, values))
    if columns is None:
        raise ValueError('%s holds no rows' % path)
    return columns, rows


def path_message(columns, rows, frame, start):
    """The Path: timed rows stamped start + (t - first t), untimed ones at 0."""
    msg = Path()
    msg.header.frame_id = frame
    msg.header.stamp = start
    timed = columns[0] == 't'
    for _, values in rows:
        pose = PoseStamped()
        pose.header.frame_id = frame
        x, y = values[-2:]
        if timed:
            pose.header.stamp = start + rospy.Duration.from_sec(values[0] - rows[0][1][0])
        pose.pose.position.x, pose.pose.position.y = x, y
        pose.pose.orientation.w = 1.0
        msg.poses.append(pose)
    return msg


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('file', help='CSV file: t,x,y or x,y rows')
    parser.add_argument('--topic', default='path', help='topic (default: path, in the node\'s namespace)')
    parser.add_argument('--frame', default=DEFAULT_FRAME, help='frame of the points (default: %(default)s)')
    parser.add_argument('--delay', type=float, default=0.0,
                        help='[s] a timed path starts this long after now (default 0)')
    args = parser.parse_args(rospy.myargv(sys.argv)[1:])
    if not math.isfinite(args.delay) or args.delay < 0.0:
        parser.error('--delay must be finite and >= 0, got %g' % args.delay)
    try:
        columns, rows = read_rows(args.file)
    except (OSError, ValueError) as e:
        sys.exit('publish_path.py: %s' % e)
    rospy.init_node('publish_path', anonymous=True)
    publisher = rospy.Publisher(args.topic, Path, queue_size=1, latch=True)
    start = rospy.Time.now() + rospy.Duration.from_sec(args.delay)
    publisher.publish(path_message(columns, rows, args.frame, start))
    rospy.loginfo('Published %d poses (%s) in frame %s on %s, latched; Ctrl-C to stop',
                  len(rows), 'timed, starting at %.3f s' % start.to_sec() if columns[0] == 't'
                  else 'untimed', args.frame, publisher.resolved_name)
    rospy.spin()


if __name__ == '__main__':
    main()
