#!/usr/bin/env bash
# Installs everything projsurf needs on a fresh Debian 12 machine (run as root), then
# configures and builds it once, in Release, into ./build: everything (the tests, benchmarks,
# the ROS node, Python), or with arguments only those targets (scripts/demo.sh: `projsurf`,
# the CLI, which is all the demo runs).
# usage: bash scripts/setup.sh [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  cmake make g++ ccache pkg-config
  libeigen3-dev libopencv-dev libpcl-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libbenchmark-dev xvfb x11-apps
  pybind11-dev python3-dev python3-numpy python3-pytest
  python3-open3d  # only for the Python test that passes an Open3D cloud; projsurf does not need it
  clang libclang-rt-14-dev libbz2-dev
)
# ROS 1 (Debian's packages) for the node in ros/; see ros/README.md.
ROS_PACKAGES=(libroscpp-dev libstd-msgs-dev libstd-srvs-dev libsensor-msgs-dev libgeometry-msgs-dev libvisualization-msgs-dev libtf2-ros-dev libtf2-eigen-dev librosbag-storage-dev python3-rosmaster python3-roslaunch
  python3-rostopic   # `rostopic echo /projsurf/result` and friends (ros/README.md)
  python3-rosservice)  # `rosservice call /projsurf/detect` (README, ros/README.md)

missing=()
for p in "${PACKAGES[@]}" "${ROS_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# ccache: paths inside the checkout are hashed relative to it, so another clone of the
# repository on the same machine reuses the objects.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=true
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
if [ $# -gt 0 ]; then
  cmake --build build -j"$(nproc)" --target "$@"
else
  cmake --build build -j"$(nproc)"
fi
