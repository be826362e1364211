#!/usr/bin/env bash
# Screenshot of rviz during a live run of launch/rotor_stack.launch (the default manoeuvre, ideal
# actuators), headless: scripts/rotor_rviz_screenshot.sh PNG [AT]
# AT: simulated seconds after start (default 15: the manoeuvre has ended). Runs its own master
# and virtual X server; needs the built package (sourced, or found by env.sh).
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
[ $# -ge 1 ] || { echo "usage: $0 PNG [AT]" >&2; exit 2; }
png=$(realpath -m "$1")
at=${2:-15}
rospack find spherical_robots > /dev/null 2>&1 || sr_source_workspace
mkdir -p "$(dirname "$png")"
work=$(mktemp -d /tmp/rotor_rviz.XXXXXX)
trap 'rm -rf "$work"' EXIT
export ROS_HOME=$work/ros_home ROS_HOSTNAME=127.0.0.1
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1]); s.close()')
export ROS_MASTER_URI=http://127.0.0.1:$port/ SHOT_PNG=$png SHOT_AT=$at SHOT_LOG=$work/roslaunch.log
export SHOT_PORT=$port
xvfb-run -a -s "-screen 0 1200x846x24" bash -c '
  roslaunch -p "$SHOT_PORT" spherical_robots rotor_stack.launch rviz:=true \
    duration:=$(python3 -c "print($SHOT_AT + 3)") > "$SHOT_LOG" 2>&1 &
  launch=$!
  until rostopic echo -n 1 /clock > /dev/null 2>&1; do sleep 0.5; done
  python3 - <<PY
import rospy, time
rospy.init_node("shot_wait", anonymous=True)
while not rospy.is_shutdown() and rospy.Time.now().to_sec() < float("$SHOT_AT"):
    time.sleep(0.05)
PY
  import -window root "$SHOT_PNG"
  wait $launch || true
'
echo "wrote $png"
