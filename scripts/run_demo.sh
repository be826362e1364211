#!/usr/bin/env bash
# The main job: installs the Debian packages, builds, starts a roscore, runs the default terrain
# stack headless in simulated time (3R robot, circle path, 200 s at 10x), records a bag, then
# plots the run and prints its tracking summary.
#   Outputs: $SPHERICAL_ROBOTS_RESULTS (default: results/ in the repository)
#   Wall-clock limit for the stack: $DEMO_TIMEOUT seconds (default 120)
# Exit status: 0 on success; non-zero if the run failed (the stack did not end normally, no bag, no
# messages, plot failed).
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$SR_ROOT"
total_start=$SECONDS

results=$(mkdir -p "${SPHERICAL_ROBOTS_RESULTS:-$SR_ROOT/results}" && cd "${SPHERICAL_ROBOTS_RESULTS:-$SR_ROOT/results}" && pwd)
touch "$results/COLCON_IGNORE"
logs=$results/logs
run=terrain_3R_circle
bag=$results/$run.bag
png=$results/$run.png
timeout_s=${DEMO_TIMEOUT:-120}

sr_step "install Debian packages" sr_install
sr_step "build (colcon, Release)" sr_build
sr_source_workspace

# Stops the process group led by $1 (started with setsid): SIGINT, then SIGKILL after 15 s.
stop_group() {
  local pid=$1 i
  kill -INT -- "-$pid" 2>/dev/null || return 0
  for i in $(seq 30); do kill -0 "$pid" 2>/dev/null || return 0; sleep 0.5; done
  sr_log "$2 did not stop on SIGINT; killing it"
  kill -KILL -- "-$pid" 2>/dev/null || true
}
core_pid='' launch_pid=''
cleanup() {
  [ -z "$launch_pid" ] || stop_group "$launch_pid" roslaunch
  [ -z "$core_pid" ] || { stop_group "$core_pid" roscore; sr_log "roscore stopped"; }
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# A real roscore with its own ROS_HOME, on 11311 if that port is free, otherwise on a free port.
rm -rf "$logs" "$bag" "$bag.active" "$png"
mkdir -p "$logs"
export ROS_HOME=$logs/ros_home ROS_HOSTNAME=127.0.0.1
port=$(python3 -c '
import socket
def bind(p):
    s = socket.socket()
    try:
        s.bind(("", p)); return s.getsockname()[1]
    except OSError:
        return None
    finally:
        s.close()
print(bind(11311) or bind(0))')
export ROS_MASTER_URI=http://127.0.0.1:$port/
setsid roscore -p "$port" > "$logs/roscore.log" 2>&1 &
core_pid=$!
for _ in $(seq 60); do
  python3 -c 'import rosgraph, sys; sys.exit(not rosgraph.is_master_online())' 2>/dev/null && break
  kill -0 "$core_pid" 2>/dev/null || { sr_log "roscore failed:"; tail -20 "$logs/roscore.log"; exit 1; }
  sleep 0.5
done
python3 -c 'import rosgraph, sys; sys.exit(not rosgraph.is_master_online())' \
  || { sr_log "roscore did not come up:"; tail -20 "$logs/roscore.log"; exit 1; }
sr_log "roscore up at $ROS_MASTER_URI (logs: $logs)"

# The stack ends by itself: the plant shuts down at t = 200 s (sim time). run_stack.py is
# roslaunch with an exit status: 0 only if the plant ended the stack (docs/conventions.md, "When a
# node dies").
launch_args=(robot:=3R path:=circle model:=paper speedup:=10 duration:=200 rviz:=false "record:=$bag")
sr_log "rosrun spherical_robots run_stack.py terrain_stack.launch ${launch_args[*]}  (wall limit ${timeout_s} s)"
launch_start=$SECONDS
setsid rosrun spherical_robots run_stack.py terrain_stack.launch "${launch_args[@]}" \
  > "$logs/roslaunch.log" 2>&1 &
launch_pid=$!
timed_out=0
while kill -0 "$launch_pid" 2>/dev/null; do
  if [ $((SECONDS - launch_start)) -ge "$timeout_s" ]; then
    timed_out=1
    sr_log "TIMEOUT: the stack still running after ${timeout_s} s wall; stopping it"
    stop_group "$launch_pid" run_stack.py
    break
  fi
  sleep 0.5
done
launch_rc=0
wait "$launch_pid" || launch_rc=$?
launch_pid=''
sr_log "run_stack.py exited with status $launch_rc after $((SECONDS - launch_start)) s wall (log: $logs/roslaunch.log)"

failed=0
[ "$timed_out" -eq 0 ] || failed=1
[ "$launch_rc" -eq 0 ] || failed=1
if [ ! -s "$bag" ]; then
  sr_log "FAILED: no bag at $bag$([ -e "$bag.active" ] && echo " (only $bag.active: the recorder did not close it)")"
  tail -25 "$logs/roslaunch.log"
  exit 1
fi
sr_log "bag: $bag ($(du -h "$bag" | cut -f1))"

python3 "$SR_ROOT/scripts/plot_terrain_run.py" "$bag" --out "$png" --paper "${png%.png}_paper.png" \
  | tee "$results/$run.summary.txt" || { sr_log "FAILED: plotting the run"; exit 1; }
sr_log "summary: $results/$run.summary.txt"
sr_log "replay it in rviz: . install/setup.sh && roslaunch spherical_robots replay.launch bag:=$bag"

cleanup
core_pid=''
sr_log "total $((SECONDS - total_start)) s"
if [ "$failed" -ne 0 ]; then
  sr_log "FAILED: the stack did not end normally within ${timeout_s} s (run_stack.py: $launch_rc)"
  exit 1
fi
sr_log "OK"
