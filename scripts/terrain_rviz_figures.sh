#!/usr/bin/env bash
# The rviz figures of docs/results.md and the README: records two terrain runs with
# launch/terrain_stack.launch (through launch/record.launch) and screenshots each replayed bag
# (scripts/rviz_screenshot.sh) late in the run, when the trail shows the whole approach:
#
#   scripts/terrain_rviz_figures.sh [OUT_DIR]     (default docs/figures; about 1.5 min)
#
#   terrain_rviz_3R_circle.png    3R robot, circle path, at t = 150 s
#   terrain_rviz_RS_diamond.png   RS robot, diamond path, at t = 150 s
# Needs the built package. Each run gets its own ROS master on a free port.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
out_dir=$(realpath -m "${1:-$SR_ROOT/docs/figures}")
rospack find spherical_robots > /dev/null 2>&1 || sr_source_workspace
mkdir -p "$out_dir"
work=$(mktemp -d /tmp/terrain_rviz_figures.XXXXXX)
trap 'rm -rf "$work"' EXIT

for case in "3R circle" "RS diamond"; do
  read -r robot path <<< "$case"
  bag=$work/terrain_${robot}_${path}.bag
  port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1]); s.close()')
  sr_log "recording $robot on the $path (160 s at 10x)"
  ROS_HOME=$work/ros_home ROS_HOSTNAME=127.0.0.1 ROS_MASTER_URI=http://127.0.0.1:$port/ \
    timeout 180 roslaunch -p "$port" spherical_robots terrain_stack.launch robot:="$robot" \
    path:="$path" duration:=160 record:="$bag" > "$work/roslaunch.log" 2>&1 \
    || { tail -20 "$work/roslaunch.log"; sr_log "FAILED: recording $robot $path"; exit 1; }
  "$SR_ROOT/scripts/rviz_screenshot.sh" "$bag" "$out_dir/terrain_rviz_${robot}_${path}.png" 150
done
