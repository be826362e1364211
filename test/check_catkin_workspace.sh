#!/usr/bin/env bash
# Tries the README's route into a user's own catkin workspace with catkin_make: a new workspace
# (default: a fresh /tmp/spherical_robots_catkin_ws.XXXXXX) whose src/ holds this package (a
# symbolic link to the source tree) beside another package that names its targets sphere_sim,
# test_surface and terrain_plant, as any package may (catkin_make builds the whole workspace as
# one CMake project, where a second target of the same name is an error); then catkin_make,
# one gtest through catkin's run_tests target and catkin_test_results, and
# `rosrun spherical_robots sphere_sim --help` in the sourced devel space.
# A second full build of the package (30 min on 2 busy cores, measured): not part of
# scripts/run_tests.sh or CI; run it by hand after changing CMakeLists.txt or package.xml:
#   test/check_catkin_workspace.sh [WORKSPACE]
# Exit status 0 only if every step succeeded.
set -euo pipefail
export PATH=/usr/bin:$PATH  # catkin needs Debian's python3 (README)
source_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
ws=${1:-$(mktemp -d /tmp/spherical_robots_catkin_ws.XXXXXX)}
log() { echo "[check_catkin_workspace] $*"; }
start=$SECONDS

mkdir -p "$ws/src/neighbour/src"
ln -sfn "$source_dir" "$ws/src/spherical_robots"
cat > "$ws/src/neighbour/package.xml" <<'EOF'
<?xml version="1.0"?>
<package format="3">
  <name>neighbour</name>
  <version>0.0.1</version>
  <description>Another package of the workspace, with short target names.</description>
  <maintainer email="neighbour@example.org">neighbour</maintainer>
  <license>BSD-3-Clause</license>
  <buildtool_depend>catkin</buildtool_depend>
</package>
EOF
cat > "$ws/src/neighbour/CMakeLists.txt" <<'EOF'
cmake_minimum_required(VERSION 3.16)
project(neighbour CXX)
find_package(catkin REQUIRED)
catkin_package()
foreach(name sphere_sim test_surface terrain_plant)
  add_executable(${name} src/main.cpp)
endforeach()
EOF
echo 'int main() { return 0; }' > "$ws/src/neighbour/src/main.cpp"

cd "$ws"
log "catkin_make in $ws (log: $ws/catkin_make.log)"
catkin_make -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3 -j2 \
  > "$ws/catkin_make.log" 2>&1 || { tail -40 "$ws/catkin_make.log"; log "FAILED: catkin_make"; exit 1; }
log "catkin_make done ($((SECONDS - start)) s)"

set +u  # catkin's setup scripts read unset variables
. devel/setup.bash
set -u
log "one gtest: catkin_make run_tests_spherical_robots_gtest_spherical_robots_test_surface"
catkin_make run_tests_spherical_robots_gtest_spherical_robots_test_surface -j2 \
  > "$ws/run_tests.log" 2>&1 || { tail -40 "$ws/run_tests.log"; log "FAILED: run_tests"; exit 1; }
catkin_test_results build/test_results/spherical_robots \
  || { log "FAILED: test results"; exit 1; }

log "rosrun spherical_robots sphere_sim --help"
help=$(rosrun spherical_robots sphere_sim --help) || { log "FAILED: rosrun sphere_sim --help"; exit 1; }
echo "$help" | head -3
log "OK ($((SECONDS - start)) s)"
