#!/usr/bin/env bash
# Live scan-to-track latency on a quiet core: the leg pipeline behind a loopback Hokuyo (10 Hz)
# and people_3d_vlp16 behind the velodyne_udp reader fed by a loopback VLP-16 (10 revolutions/s),
# each with the reader and the stages pinned to one core (taskset) and the loopback device on
# another. Beside each figure, the CPU steal over the measurement (the share of time the
# hypervisor gave the core to someone else: on a VM it shows as latency no code can remove).
#   scripts/live_latency.sh [BUILD_DIR]   (default build, a Release build; PEDTRACK_LIVE_FRAMES
#                                          scans per pipeline, 300)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
frames=${PEDTRACK_LIVE_FRAMES:-300}
cores=$(nproc)
[ "$cores" -ge 2 ] || { echo "live_latency.sh: needs two cores (one for the device)" >&2; exit 2; }
stage_cpu=$((cores - 1))
device_cpu=0

# "steal total" of the whole machine and of the stage core, from /proc/stat (jiffies).
ticks() {
  awk -v core="cpu$stage_cpu" '$1 == "cpu" || $1 == core {
    s = 0; for (i = 2; i <= NF; i++) s += $i; printf "%s %s ", $9, s }' /proc/stat
}
percent() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", (b > 0 ? 100 * a / b : 0) }'; }

printf '%-40s %s\n' "pipeline (pinned to cpu$stage_cpu, device on cpu$device_cpu)" \
  "latency, and CPU steal over the run (machine / pinned core)"
measure() {
  local name=$1 binary=$2 test=$3 out before after
  read -r -a before <<< "$(ticks)"
  out=$(cd "$build" && PEDTRACK_DEVICE_CPU=$device_cpu PEDTRACK_LIVE_FRAMES=$frames \
    taskset -c "$stage_cpu" "$build/bin/$binary" "$test" 2>&1) || {
    echo "$out" | tail -30
    echo "live_latency.sh: $binary failed" >&2
    exit 1
  }
  read -r -a after <<< "$(ticks)"
  local line
  line=$(echo "$out" | grep -E '^(hokuyo|velodyne_udp) live:' | sed 's/^[a-z_]* live: //')
  printf '%-40s %s; steal %s %% / %s %%\n' "$name" "$line" \
    "$(percent $((after[0] - before[0])) $((after[1] - before[1])))" \
    "$(percent $((after[2] - before[2])) $((after[3] - before[3])))"
}
measure "2D legs, people_2d_legs (Hokuyo)" test_hokuyo_loopback \
  "hokuyo loopback: tracks come out of a live leg pipeline"
measure "3D, people_3d_vlp16 (velodyne_udp)" test_velodyne_udp \
  "velodyne_udp: a live 3D pipeline tracks the people of every revolution"
