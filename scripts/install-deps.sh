#!/usr/bin/env bash
# Installs the Debian bookworm packages pedtrack builds and tests with (only those missing).
set -euo pipefail
packages=(
  cmake g++ make ccache pkg-config clang-format zlib1g-dev
  clang libclang-rt-14-dev python3               # scripts/check.sh: ASan + UBSan build, libFuzzer
  lld                                          # scripts/check.sh: links both builds faster
  libmrpt-dev mrpt-apps mrpt-common            # MRPT 2.5: observations, config, drivers, rawlog-edit, sample datasets
  libboost-filesystem-dev libboost-program-options-dev
  catch2
  coinor-libipopt-dev                          # Ipopt: mhe_mlesac (P0) and the circle-fit test
  libopencv-dev                                # pedtrack render: drawing, PNG, MP4 (FFmpeg backend); SVM
  libnanoflann-dev                             # k-NN KD-tree (also pulled in by libmrpt-dev)
  librosbag-storage-dev libmrpt-ros1bridge-dev  # ROS1 bag replay
  libtf2-dev libtf2-msgs-dev libsensor-msgs-dev libnav-msgs-dev
  ros-core libroscpp-dev libtf2-ros-dev        # `pedtrack ros` (roscore and rosbag play for its test)
  libvisualization-msgs-dev libgeometry-msgs-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
