#!/usr/bin/env bash
# The rviz figures of docs/results.md and the README: records each stack's run (through
# launch/record.launch) and screenshots the replayed bag (scripts/rviz_screenshot.sh) late in the
# run, when the trail shows the approach; the Norma, rotor and FreeBOT bags are also plotted
# (plot_norma_run.py, plot_rotor_run.py, plot_freebot_run.py: *_run*.png beside the screenshots):
#
#   scripts/rviz_figures.sh [OUT_DIR [NAME...]]   (default docs/figures, all; about 4.5 min)
#
#   terrain_rviz_3R_circle.png    terrain stack, 3R robot, circle path, at t = 150 s
#   terrain_rviz_RS_diamond.png   terrain stack, RS robot, diamond path, at t = 150 s
#   roller_rviz_circle.png        roller stack, circle, at t = 60 s
#   norma_rviz_paper.png          Norma stack, paper controller, at t = 55 s (real time)
#   rotor_rviz.png                rotor stack, default two-step manoeuvre, at t = 15 s (ended)
#   freebot_rviz.png              FreeBOT stack, default targets, at t = 26 s (at target C)
#   norma_run_paper.png, rotor_run.png, freebot_run.png: the plots of those three bags
#   rotor_run_corrected.png       rotor stack with corrections:=3 (plot only, no screenshot)
# Needs the built package. Each run gets its own ROS master on a free port.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
out_dir=$(realpath -m "${1:-$SR_ROOT/docs/figures}")
rospack find spherical_robots > /dev/null 2>&1 || sr_source_workspace
mkdir -p "$out_dir"
work=$(mktemp -d /tmp/rviz_figures.XXXXXX)
trap 'rm -rf "$work"' EXIT

wanted=("${@:2}")

# record STACK NAME AT DURATION LAUNCH_ARGS...: records a run and screenshots it at bag time AT
# (AT "-": no screenshot), if NAME is wanted: no names given, or NAME among them.
record() {
  local stack=$1 name=$2 at=$3 duration=$4 bag=$work/$2.bag port
  shift 4
  [ ${#wanted[@]} -eq 0 ] || [[ " ${wanted[*]} " == *" $name "* ]] || return 0
  port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1]); s.close()')
  sr_log "recording $name ($duration s)"
  ROS_HOME=$work/ros_home ROS_HOSTNAME=127.0.0.1 ROS_MASTER_URI=http://127.0.0.1:$port/ \
    timeout $((duration + 120)) roslaunch -p "$port" spherical_robots "${stack}_stack.launch" "$@" \
    duration:="$duration" record:="$bag" > "$work/roslaunch.log" 2>&1 \
    || { tail -20 "$work/roslaunch.log"; sr_log "FAILED: recording $name"; exit 1; }
  [ "$at" = - ] || STACK=$stack "$SR_ROOT/scripts/rviz_screenshot.sh" "$bag" "$out_dir/$name.png" "$at"
  case $stack in
    norma|rotor|freebot)
      python3 "$SR_ROOT/scripts/plot_${stack}_run.py" "$bag" "$out_dir/${name/rviz/run}.png" \
        "$stack stack, recorded run ($*)" ;;
  esac
}

record terrain terrain_rviz_3R_circle 150 160 robot:=3R path:=circle
record terrain terrain_rviz_RS_diamond 150 160 robot:=RS path:=diamond
record roller roller_rviz_circle 60 100 path:=circle
record norma norma_rviz_paper 55 60 controller:=paper speedup:=1
record rotor rotor_rviz 15 17
record rotor rotor_rviz_corrected - 50 corrections:=3
record freebot freebot_rviz 26 28
