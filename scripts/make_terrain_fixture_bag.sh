#!/usr/bin/env bash
# Records the small bag the replay tests use (test/data/terrain_3R_circle_fixture.bag): the default
# terrain stack (3R robot, circle path, paper model, 10x simulated time) for DURATION simulated
# seconds, recorded by launch/record.launch (through terrain_stack.launch record:=...), then
# rewritten with only the topics the tests need, bag time = header stamp, LZ4-compressed.
#
#   scripts/make_terrain_fixture_bag.sh [OUT.bag] [DURATION]     (defaults: the test's bag, 25)
#
# Needs the built package (it sources install/setup.sh of the repository if roslaunch cannot find
# spherical_robots). Runs its own master on a free port, so it can run beside another ROS master.
# Kept topics: /tf, /tf_static, and under /sphere: terrain_state, tracking_error, actuators/command,
# target, desired_path, trail, terrain_marker (about 0.85 MB for 25 s). Left out: odom,
# actuators/state, diagnostics and cmd_vel, which no test reads (odom alone would double the size).
# Bag time = header stamp: the recorder stamps a message when it receives it, usually one 0.01 s
# clock tick before the plant's stamp (the /clock update reaches it after the message), so rosbag
# play would deliver terrain_state earlier than the live controller saw it. Latched messages and
# messages stamped 0 keep their recorded time.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
out=$(realpath -m "${1:-$SR_ROOT/test/data/terrain_3R_circle_fixture.bag}")
duration=${2:-25}
rospack find spherical_robots > /dev/null 2>&1 || sr_source_workspace

work=$(mktemp -d /tmp/terrain_fixture.XXXXXX)
trap 'rm -rf "$work"' EXIT
export ROS_HOME=$work/ros_home ROS_HOSTNAME=127.0.0.1
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1]); s.close()')
export ROS_MASTER_URI=http://127.0.0.1:$port/

sr_log "recording ${duration} s of the terrain stack (3R, circle) on port $port"
timeout 180 roslaunch -p "$port" spherical_robots terrain_stack.launch robot:=3R path:=circle \
  model:=paper speedup:=10 duration:="$duration" record:="$work/raw.bag" > "$work/roslaunch.log" 2>&1 \
  || { tail -20 "$work/roslaunch.log"; sr_log "FAILED: roslaunch"; exit 1; }
[ -s "$work/raw.bag" ] || { tail -20 "$work/roslaunch.log"; sr_log "FAILED: no bag"; exit 1; }

mkdir -p "$(dirname "$out")"
python3 - "$work/raw.bag" "$out" <<'PY'
import sys
import rosbag
import rospy

KEEP = {'/tf', '/tf_static', '/sphere/terrain_state', '/sphere/tracking_error',
        '/sphere/actuators/command', '/sphere/target', '/sphere/desired_path', '/sphere/trail',
        '/sphere/terrain_marker'}


def stamp(msg, latched):
    if latched:
        return None
    if hasattr(msg, 'header'):
        s = msg.header.stamp
    elif getattr(msg, 'transforms', None):
        s = msg.transforms[0].header.stamp
    else:
        return None
    return s if s > rospy.Time(0) else None


with rosbag.Bag(sys.argv[1]) as raw, rosbag.Bag(sys.argv[2], 'w', compression='lz4') as out:
    for topic, msg, t, header in raw.read_messages(topics=sorted(KEEP), return_connection_header=True):
        latched = header.get('latching') in ('1', b'1')
        out.write(topic, msg, stamp(msg, latched) or t, connection_header=header)
PY
rosbag info "$out"
sr_log "wrote $out ($(du -h "$out" | cut -f1))"
