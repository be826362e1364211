# Shared set-up for scripts/run_demo.sh and scripts/run_tests.sh. Source it, do not run it.
# The colcon workspace is the repository root itself: build/, install/ and log/ beside package.xml
# (git-ignored; colcon puts a COLCON_IGNORE in each, so they are never crawled as packages).

# catkin needs Debian's python3 (with catkin_pkg); another python3 earlier on PATH lacks it.
export PATH=/usr/bin:$PATH
SR_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SR_NAME=$(basename "$0" .sh)

sr_log() { echo "[$SR_NAME] $*"; }

# sr_step LABEL COMMAND...: runs COMMAND, then prints how long it took.
sr_step() {
  local label=$1 start=$SECONDS
  shift
  sr_log "$label ..."
  "$@"
  sr_log "$label done ($((SECONDS - start)) s)"
}

sr_install() { bash "$SR_ROOT/scripts/install_deps.sh"; }

# Incremental: a second build only recompiles what changed. Compiler output goes to
# log/latest_build/spherical_robots/stderr.log; its tail is shown if the build fails.
sr_build() {
  local stderr_log=$SR_ROOT/log/latest_build/spherical_robots/stderr.log warnings
  (cd "$SR_ROOT" && colcon build --base-paths . --build-base build --install-base install \
    --event-handlers console_stderr- \
    --cmake-args -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3) \
    || { [ ! -f "$stderr_log" ] || tail -60 "$stderr_log"; return 1; }
  warnings=$(grep -c 'warning:' "$stderr_log" 2>/dev/null || true)
  [ "${warnings:-0}" -eq 0 ] || sr_log "$warnings compiler warnings: see ${stderr_log#"$SR_ROOT"/}"
}

# Puts the built package (nodes, launch files, python message classes) into the environment.
sr_source_workspace() {
  set +u  # colcon's setup.sh reads unset variables
  . "$SR_ROOT/install/setup.sh"
  set -u
}
