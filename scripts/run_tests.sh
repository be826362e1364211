#!/usr/bin/env bash
# Installs the Debian packages, builds, and runs every gtest and rostest of the package
# (colcon test, under a virtual X server; four tests at a time on two cores: a rostest spends much
# of its time starting, joining and waiting, in lock-step a stack's results do not depend on how
# busy the machine is, and the replay tests share the display by a lock) and the
# fuzz targets for a fixed number of executions (scripts/fuzz.sh --short), then prints the summary.
# Exit status: 0 only if at least one test ran, none failed and the fuzzing found nothing.
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$SR_ROOT"
total_start=$SECONDS

sr_step "install Debian packages" sr_install
sr_step "build (colcon, Release)" sr_build
sr_source_workspace

# rostest starts its own master on a random port; its logs go to a fresh ROS_HOME.
ROS_HOME=$(mktemp -d /tmp/spherical_robots_tests.XXXXXX)
export ROS_HOME
unset ROS_MASTER_URI
# Results of an earlier run must not count again.
rm -rf build/spherical_robots/test_results

# stdin from /dev/null: rosbag play (the replay and bag regression tests) reads keys from it, and
# a space typed or text fed into the terminal would pause its clock (a regular file in place of
# /dev/null, holding text, froze a bag test for its whole 120 s).
test_rc=0
sr_step "run gtests and rostests (colcon test, xvfb-run)" \
  xvfb-run -a -s "-screen 0 1280x1024x24" \
  colcon test --base-paths . --build-base build --install-base install \
    --event-handlers console_cohesion+ --return-code-on-test-failure \
    --ctest-args --timeout 900 -j4 < /dev/null \
  || test_rc=$?

# The libFuzzer targets, a fixed number of executions each, in their own clang build
# (build-fuzz/, apart from colcon's); scripts/fuzz.sh without --short is the long form.
fuzz_rc=0
sr_step "fuzz the core's entry points (scripts/fuzz.sh --short)" scripts/fuzz.sh --short || fuzz_rc=$?

colcon test-result --test-result-base build --verbose || true
summary=$(colcon test-result --test-result-base build | grep '^Summary:' || true)
sr_log "${summary:-Summary: no test results found}   (ROS logs: $ROS_HOME/log)"
sr_log "total $((SECONDS - total_start)) s"

counts=$(echo "$summary" |
  sed -nE 's/^Summary: ([0-9]+) tests, ([0-9]+) errors?, ([0-9]+) failures?, ([0-9]+) skipped.*/\1 \2 \3 \4/p')
read -r ran errors failures skipped <<< "${counts:-0 0 0 0}"
if [ "$ran" -eq 0 ]; then
  sr_log "FAILED: no tests ran"; exit 1
fi
# rostest counts a test node that died before reporting (an exception at shutdown) as a success
# with no test case: its rosunit result then holds none.
silent=$(grep -L "<testcase" build/spherical_robots/test_results/spherical_robots/rosunit-*.xml \
         2>/dev/null || true)
if [ -n "$silent" ]; then
  sr_log "FAILED: test nodes that reported no test case: $(echo $silent | xargs -n1 basename | tr '\n' ' ')"
  exit 1
fi
if [ "$errors" -ne 0 ] || [ "$failures" -ne 0 ] || [ "$test_rc" -ne 0 ]; then
  sr_log "FAILED: $failures failures, $errors errors (colcon test exit $test_rc)"; exit 1
fi
if [ "$fuzz_rc" -ne 0 ]; then
  sr_log "FAILED: scripts/fuzz.sh --short (exit $fuzz_rc): its findings are named above"; exit 1
fi
sr_log "OK: $ran tests ran ($skipped of them skipped), none failed"
