#!/usr/bin/env bash
# Records the small bags the replay tests use (test/data/<stack>_fixture.bag... see below): a
# stack's default run for DURATION simulated seconds, recorded by launch/record.launch (through
# the stack's record:=...), then rewritten with only the topics the tests need, bag time = header
# stamp, LZ4-compressed.
#
#   test/make_fixture_bag.sh terrain [OUT.bag] [DURATION]  (test/data/terrain_3R_circle_fixture.bag, 25)
#   test/make_fixture_bag.sh roller  [OUT.bag] [DURATION]  (test/data/roller_2R_circle_fixture.bag, 25)
#   test/make_fixture_bag.sh norma   [OUT.bag] [DURATION]  (test/data/norma_paper_fixture.bag, 45)
#   test/make_fixture_bag.sh rotor   [OUT.bag] [DURATION]  (test/data/rotor_k2.5_n2_fixture.bag, 14)
#   test/make_fixture_bag.sh freebot [OUT.bag] [DURATION]  (test/data/freebot_ABC_fixture.bag, 20)
#
# Needs the built package (it sources install/setup.sh of the repository if roslaunch cannot find
# spherical_robots). Runs its own master on a free port, so it can run beside another ROS master.
# Kept topics: /tf, /tf_static, and under the stack's namespace what rviz and the bag tests read:
# terrain: odom (the controller's input), terrain_state (the contact points), tracking_error,
# actuators/command, target, desired_path, trail, terrain_marker (about 1 MB for 25 s); roller:
# the same plus roller_markers; norma:
# tracking_error, target, desired_path, trail; rotor: planned_path, contact_curve, driven_path;
# freebot: freebot_markers, ik_target, trail. Left out: actuators/state, diagnostics,
# cmd_vel, norma_state (1 kHz), freebot_state, joint_states (the tf they make is kept), which no
# test reads.
# Bag time = header stamp: the recorder stamps a message when it receives it, usually one 0.01 s
# clock tick before the plant's stamp (the /clock update reaches it after the message), so rosbag
# play would deliver terrain_state earlier than the live controller saw it. Latched messages and
# messages stamped 0 keep their recorded time.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/../scripts/env.sh"
stack=${1:?usage: $0 terrain|roller|norma|rotor|freebot [OUT.bag] [DURATION]}
case $stack in
  terrain) ns=sphere; default=terrain_3R_circle_fixture.bag
           # the paper's law: test/controller_bag_regression.test derives its tolerances from eq 55
           launch=(terrain_stack.launch robot:=3R path:=circle model:=paper law:=paper speedup:=10)
           keep="odom terrain_state tracking_error actuators/command target desired_path trail terrain_marker" ;;
  roller)  ns=roller; default=roller_2R_circle_fixture.bag
           launch=(roller_stack.launch path:=circle speedup:=10)
           keep="odom terrain_state tracking_error actuators/command target desired_path trail terrain_marker roller_markers" ;;
  norma)   ns=norma; default=norma_paper_fixture.bag
           launch=(norma_stack.launch controller:=paper speedup:=1)
           keep="tracking_error target desired_path trail"; default_duration=45 ;;
  rotor)   ns=rotor; default=rotor_k2.5_n2_fixture.bag
           launch=(rotor_stack.launch speedup:=1)
           keep="planned_path contact_curve driven_path"; default_duration=14 ;;
  freebot) ns=freebot; default=freebot_ABC_fixture.bag
           launch=(freebot_stack.launch speedup:=2)
           keep="freebot_markers ik_target trail"; default_duration=20 ;;
  *) echo "unknown stack '$stack' (terrain | roller | norma | rotor | freebot)" >&2; exit 2 ;;
esac
out=$(realpath -m "${2:-$SR_ROOT/test/data/$default}")
duration=${3:-${default_duration:-25}}
rospack find spherical_robots > /dev/null 2>&1 || sr_source_workspace

work=$(mktemp -d /tmp/fixture_bag.XXXXXX)
trap 'rm -rf "$work"' EXIT
export ROS_HOME=$work/ros_home ROS_HOSTNAME=127.0.0.1
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1]); s.close()')
export ROS_MASTER_URI=http://127.0.0.1:$port/

sr_log "recording ${duration} s of the $stack stack on port $port"
timeout 180 roslaunch -p "$port" spherical_robots "${launch[@]}" duration:="$duration" \
  record:="$work/raw.bag" > "$work/roslaunch.log" 2>&1 \
  || { tail -20 "$work/roslaunch.log"; sr_log "FAILED: roslaunch"; exit 1; }
[ -s "$work/raw.bag" ] || { tail -20 "$work/roslaunch.log"; sr_log "FAILED: no bag"; exit 1; }

mkdir -p "$(dirname "$out")"
python3 - "$work/raw.bag" "$out" "$ns" "$keep" <<'PY'
import sys
import rosbag
import rospy

KEEP = {'/tf', '/tf_static'} | {'/%s/%s' % (sys.argv[3], t) for t in sys.argv[4].split()}


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
