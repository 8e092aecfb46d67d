#!/usr/bin/env bash
# Runs every libFuzzer target of a PEDTRACK_FUZZ build (scripts/check.sh makes one) for a bounded
# time each, on seeds made from the repository's real files, after replaying every input kept
# in fuzz/regressions/TARGET/ (crashes found earlier, fixed since). A crash is written to
# BUILD/fuzz-crashes/ and fails the script.
#   scripts/fuzz.sh [BUILD_DIR]      (default build-check; PEDTRACK_FUZZ_SECONDS per target, 30;
#                                     PEDTRACK_FUZZ_SEED, 1)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build-check}" && pwd)
secs=${PEDTRACK_FUZZ_SECONDS:-30}
# A fixed seed (PEDTRACK_FUZZ_SEED, 1) makes a CI run explore what the same run did here; set
# another, or 0 for a random one, to search further.
seed=${PEDTRACK_FUZZ_SEED:-1}
bin=$build/bin
work=$build/fuzz-work
crashes=$build/fuzz-crashes
rm -rf "$work"
mkdir -p "$work" "$crashes"
cd "$root"

# Seed corpora from real files: the shipped pipelines and scenarios, a model, the outputs and
# a recording of a short run, VLP-16 packets and a Hokuyo session.
mkdir -p "$work"/{pipeline_ini,scenario,csv,model,velodyne,rawlog,rosbag,scip,kitti}
cp configs/*.ini "$work/pipeline_ini/"
cp configs/scenarios/*.ini "$work/scenario/"
cp models/torso_svm.yml "$work/model/"
"$bin/pedtrack" run configs/people_2d_legs.ini --max-frames 12 --out "$work/run" \
  --record "$work/rawlog/legs.rawlog" -q
for f in tracks truth detections clusters; do
  [ -f "$work/run/$f.csv" ] && head -n 40 "$work/run/$f.csv" > "$work/csv/$f.csv"
done
python3 scripts/fuzz_seeds.py "$work"
# KITTI: a tracking label file and the detector's lines of the shared data (when there), and the
# kitti_tracks.txt and detection files the tests wrote.
kitti_data=${PEDTRACK_DATA:-$root/../shared/data}/kitti_tracking
for f in label_02/0017.txt pointrcnn_pedestrian/0017.txt; do
  [ -f "$kitti_data/$f" ] && head -n 60 "$kitti_data/$f" > "$work/kitti/$(echo "$f" | tr / _)"
done
find "$build/Testing/work" \( -name 'kitti_tracks.txt' -o -name 'dets.txt' -o -name 'labels.txt' \) \
  -size -64k -exec sh -c 'cp "$1" "$2/$(echo "$1" | md5sum | cut -c1-8).txt"' _ {} "$work/kitti" \; 2>/dev/null || true
# ROS bags: the small ones test_rosbag writes with rosbag_storage (scans, /tf, odometry; the
# test suite runs before this in scripts/check.sh). No bag writer ships for Python here.
find "$build/Testing/work" -name '*.bag' -size -64k -exec cp {} "$work/rosbag/" \; 2>/dev/null || true
# The chunk scan of bags cut short: the same bags, whole and cut at half.
mkdir -p "$work/bag_recover"
for b in "$work"/rosbag/*.bag; do
  [ -f "$b" ] || continue
  cp "$b" "$work/bag_recover/"
  head -c $(( $(stat -c %s "$b") / 2 )) "$b" > "$work/bag_recover/half-$(basename "$b")"
done
[ -n "$(ls "$work/rosbag")" ] || echo "fuzz.sh: no small bag under $build/Testing/work (run the tests first): fuzz_rosbag starts without a seed"

declare -A max_len=([fuzz_pipeline_ini]=16384 [fuzz_scenario]=16384 [fuzz_csv]=16384
  [fuzz_model]=131072 [fuzz_velodyne]=12060 [fuzz_rawlog]=65536 [fuzz_rosbag]=65536
  [fuzz_bag_recover]=65536 [fuzz_scip]=16384 [fuzz_kitti]=16384)
declare -A corpus=([fuzz_pipeline_ini]=pipeline_ini [fuzz_scenario]=scenario [fuzz_csv]=csv
  [fuzz_model]=model [fuzz_velodyne]=velodyne [fuzz_rawlog]=rawlog [fuzz_rosbag]=rosbag
  [fuzz_bag_recover]=bag_recover [fuzz_scip]=scip [fuzz_kitti]=kitti)
# Memory limits. MRPT's archive reader and rosbag_storage trust 32-bit length fields: a corrupt
# string or record header makes them allocate (MRPT: and zero-fill) up to 4 GiB before the read
# fails and the source reports the file as broken. That is a spike, not a crash, and it is in
# those libraries, so the targets that read bags or rawlogs allow one allocation of 4 GiB (the
# chunk scan of fuzz_bag_recover decompresses a chunk of up to 1 GiB); the others 2 GB. Their
# RSS limit leaves room for the fuzzer's own memory beside that spike: fuzz_rawlog peaked at
# 4,537 MB (a 4 GiB string plus ~440 MB of ASan and corpus), within 163 MB of the old 4,700.
declare -A limits=([fuzz_rawlog]="-malloc_limit_mb=4200 -rss_limit_mb=5632"
  [fuzz_rosbag]="-malloc_limit_mb=4200 -rss_limit_mb=5632"
  [fuzz_bag_recover]="-malloc_limit_mb=4200 -rss_limit_mb=5632")
status=0
printf '%-18s %8s %10s %8s  %s\n' target seconds runs corpus result
for target in fuzz_pipeline_ini fuzz_scenario fuzz_csv fuzz_model fuzz_velodyne fuzz_rawlog \
  fuzz_rosbag fuzz_bag_recover fuzz_scip fuzz_kitti; do
  [ -x "$bin/$target" ] || { printf '%-18s not built\n' "$target"; continue; }
  log=$work/$target.log
  start=$(date +%s)
  result=ok
  # Earlier crashes first: each must now pass.
  if compgen -G "fuzz/regressions/$target/*" > /dev/null; then
    # shellcheck disable=SC2086
    "$bin/$target" ${limits[$target]:--rss_limit_mb=2048} fuzz/regressions/$target/* \
      > "$log.regressions" 2>&1 || result="regression failed"
  fi
  if [ "$result" = ok ]; then
    # shellcheck disable=SC2086
    "$bin/$target" "$work/${corpus[$target]}" -max_total_time="$secs" -seed="$seed" \
      ${limits[$target]:--rss_limit_mb=2048} \
      -timeout=20 -max_len="${max_len[$target]}" -artifact_prefix="$crashes/$target-" \
      -print_final_stats=1 > "$log" 2>&1 || result="CRASH (see $log, $crashes)"
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" 2>/dev/null | grep -o '[0-9]*$' || echo -)
  size=$(ls "$work/${corpus[$target]}" | wc -l)
  printf '%-18s %8s %10s %8s  %s\n' "$target" "$(( $(date +%s) - start ))" "$runs" "$size" "$result"
  [ "$result" = ok ] || status=1
done
exit $status
