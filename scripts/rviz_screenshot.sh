#!/usr/bin/env bash
# Screenshot of rviz showing a recorded bag at a given bag time, headless:
#
#   scripts/rviz_screenshot.sh BAG PNG [AT]     (AT: seconds of bag time, default: 1 s before its end)
#   STACK=roller scripts/rviz_screenshot.sh ...  (the stack that recorded it: terrain (default) |
#                                                roller | norma | rotor | freebot)
#
# Under its own virtual X server (xvfb-run) and its own ROS master, it runs
# `roslaunch spherical_robots replay.launch bag:=BAG start:=...` from 6 s before AT (rviz starts
# and draws the robot and the trail meanwhile; replay_latched.py supplies the terrain and the
# desired path, which the bag holds only at its start), waits until /clock reaches AT and saves the
# rviz window (`import -window`, 1200x846 as in rviz/<stack>.rviz) to PNG. Needs the built package.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
[ $# -ge 2 ] || { echo "usage: $0 BAG PNG [AT]" >&2; exit 2; }
bag=$(realpath "$1")
png=$(realpath -m "$2")
rospack find spherical_robots > /dev/null 2>&1 || sr_source_workspace
read -r begin end < <(python3 -c '
import rosbag, sys
b = rosbag.Bag(sys.argv[1]); print(b.get_start_time(), b.get_end_time())' "$bag")
at=${3:-$(python3 -c "print(max($begin, $end - 1.0))")}
start=$(python3 -c "print(max(0.0, $at - 6.0 - $begin))")  # rosbag play --start: from the bag's start
mkdir -p "$(dirname "$png")"

work=$(mktemp -d /tmp/rviz_screenshot.XXXXXX)
trap 'rm -rf "$work"' EXIT
export ROS_HOME=$work/ros_home ROS_HOSTNAME=127.0.0.1
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1]); s.close()')
export ROS_MASTER_URI=http://127.0.0.1:$port/ SHOT_BAG=$bag SHOT_PNG=$png SHOT_AT=$at SHOT_START=$start
export SHOT_PORT=$port SHOT_LOG=$work/roslaunch.log SHOT_STACK=${STACK:-terrain}

sr_log "replaying $(basename "$bag") from $start s into it, screenshot at bag time $at s"
xvfb-run -a -s "-screen 0 1280x1024x24" bash -c '
  set -u
  setsid roslaunch -p "$SHOT_PORT" spherical_robots replay.launch bag:="$SHOT_BAG" \
    stack:="$SHOT_STACK" start:="$SHOT_START" > "$SHOT_LOG" 2>&1 &
  pid=$!
  # The /clock of the replay reaches AT (bag start time + offset), within 90 s of wall time.
  python3 - <<PY
import sys, time, rosgraph, rospy
from rosgraph_msgs.msg import Clock
deadline = time.time() + 90
while not rosgraph.is_master_online():
    if time.time() > deadline:
        sys.exit("no ROS master")
    time.sleep(0.2)
rospy.init_node("rviz_screenshot_wait", anonymous=True, disable_signals=True)
target = float("$SHOT_AT")
while time.time() < deadline:
    try:
        if rospy.wait_for_message("/clock", Clock, timeout=5).clock.to_sec() >= target:
            sys.exit(0)
    except rospy.ROSException:
        pass
sys.exit("the replay did not reach t = %g s" % target)
PY
  rc=$?
  [ $rc -ne 0 ] || import -window "$SHOT_STACK.rviz - RViz" "$SHOT_PNG" || rc=$?
  kill -INT -- "-$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  exit $rc
' || { tail -20 "$work/roslaunch.log"; sr_log "FAILED"; exit 1; }
sr_log "wrote $png ($(identify -format '%wx%h, %k colours' "$png"))"
