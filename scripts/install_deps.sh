#!/usr/bin/env bash
# Installs every Debian 12 package the build, the stacks and the tests need (run as root).
set -euo pipefail
packages=(
  # build
  build-essential cmake catkin colcon python3-colcon-ros python3-colcon-cmake
  python3-colcon-test-result python3-colcon-output python3-colcon-parallel-executor
  python3-colcon-recursive-crawl python3-colcon-package-information python3-colcon-library-path
  python3-colcon-defaults python3-colcon-pkg-config python3-colcon-package-selection
  python3-catkin-pkg python3-setuptools ros-message-generation ros-message-runtime
  # ROS libraries and messages
  ros-base-dev libtf2-ros-dev libtf2-msgs-dev libtf2-eigen-dev
  libnav-msgs-dev libvisualization-msgs-dev libgeometry-msgs-dev libsensor-msgs-dev
  libdiagnostic-msgs-dev libstd-msgs-dev libstd-srvs-dev libdiagnostic-updater-dev
  # the FreeBOT goals and the rotor manoeuvres as actions (action/)
  libactionlib-dev libactionlib-msgs-dev
  # every node as a nodelet: the library, pluginlib, and the `nodelet` manager and loader
  libnodeletlib-dev pluginlib-dev libnodeletlib-tools
  # parameters changed while a stack runs: the C++ server, the cfg generator and the client
  libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure
  # core libraries (liburdfdom-dev: urdf_parser/urdf_parser.h, linked directly; no ROS urdf)
  libeigen3-dev liburdfdom-dev libboost-dev libyaml-cpp-dev
  # height maps: 16-bit PNG (src/config/height_map_files.cpp)
  libpng-dev
  # the fuzz targets and the sanitized gtests (scripts/fuzz.sh, scripts/sanitize_tests.sh):
  # libFuzzer ships only with clang's runtime libraries (libclang-rt), not with GCC
  clang libclang-rt-14-dev
  # tests and benchmarks
  libgtest-dev libgmock-dev googletest libbenchmark-dev librostest-dev python3-rostest catkin-lint
  topic-tools
  # running stacks, bags, plots, rviz
  python3-rospy python3-roslaunch python3-rosbag python3-rosnode python3-rostopic rosbash
  python3-nav-msgs python3-geometry-msgs python3-sensor-msgs python3-diagnostic-msgs
  python3-std-msgs python3-std-srvs python3-tf2-ros python3-tf2-msgs python3-visualization-msgs
  python3-diagnostic-updater python3-interactive-markers python3-actionlib python3-actionlib-msgs
  ros-robot-state-publisher rviz xvfb xauth x11-utils imagemagick
  # each stack's diagnostic aggregator: aggregator_node (tools) and its analyzer plugins (dev)
  libdiagnostic-aggregator-tools libdiagnostic-aggregator-dev
  python3-numpy python3-matplotlib
  # derivations/derive_norma_dynamics.py
  python3-sympy
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "[install_deps] installing ${#missing[@]} Debian packages"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" > /tmp/spherical_robots_apt.log 2>&1 \
    || { tail -30 /tmp/spherical_robots_apt.log; exit 1; }
fi
