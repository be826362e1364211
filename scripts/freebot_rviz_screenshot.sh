#!/usr/bin/env bash
# Screenshot of rviz showing the live FreeBOT stack (launch/freebot_stack.launch, rviz:=true,
# default targets, 1x real time) once it has reached target C, headless:
#
#   scripts/freebot_rviz_screenshot.sh PNG [AT]   (AT: seconds of simulated time, default 26)
#
# Under its own virtual X server (xvfb-run) and its own ROS master; saves the rviz window
# (1200x846 as in rviz/freebot.rviz) to PNG. Needs the built package (or a sourced workspace).
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
[ $# -ge 1 ] || { echo "usage: $0 PNG [AT]" >&2; exit 2; }
png=$(realpath -m "$1")
rospack find spherical_robots > /dev/null 2>&1 || sr_source_workspace
mkdir -p "$(dirname "$png")"

work=$(mktemp -d /tmp/freebot_screenshot.XXXXXX)
trap 'rm -rf "$work"' EXIT
export ROS_HOME=$work/ros_home ROS_HOSTNAME=127.0.0.1
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1]); s.close()')
export ROS_MASTER_URI=http://127.0.0.1:$port/ SHOT_PNG=$png SHOT_AT=${2:-26} SHOT_PORT=$port
export SHOT_LOG=$work/roslaunch.log

sr_log "FreeBOT stack with rviz, screenshot at simulated t = $SHOT_AT s"
xvfb-run -a -s "-screen 0 1280x1024x24" bash -c '
  set -u
  setsid roslaunch -p "$SHOT_PORT" spherical_robots freebot_stack.launch rviz:=true speedup:=1 \
    > "$SHOT_LOG" 2>&1 &
  pid=$!
  python3 - <<PY
import sys, time, rosgraph, rospy
from rosgraph_msgs.msg import Clock
deadline = time.time() + 120
while not rosgraph.is_master_online():
    if time.time() > deadline:
        sys.exit("no ROS master")
    time.sleep(0.2)
rospy.init_node("freebot_screenshot_wait", anonymous=True, disable_signals=True)
while time.time() < deadline:
    try:
        if rospy.wait_for_message("/clock", Clock, timeout=5).clock.to_sec() >= float("$SHOT_AT"):
            sys.exit(0)
    except rospy.ROSException:
        pass
sys.exit("the stack did not reach t = $SHOT_AT s")
PY
  rc=$?
  [ $rc -ne 0 ] || import -window "freebot.rviz - RViz" "$SHOT_PNG" || rc=$?
  kill -INT -- "-$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  exit $rc
' || { tail -20 "$work/roslaunch.log"; sr_log "FAILED"; exit 1; }
sr_log "wrote $png ($(identify -format '%wx%h, %k colours' "$png"))"
