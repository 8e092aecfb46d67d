#!/usr/bin/env bash
# The 3D person classifiers on scene types left out of training (leave one scene type out):
# samples of five scene types (classify_scene, street_moving, park_static, plaza_groups,
# parking_static; seeds 601-603, none of the shipped models' training seeds), segmented by
# people_3d_vlp16.ini's own stages as the shipped forest's training data is, are collected once;
# for each type, k-NN (P2's six features), SVM (all features) and the random forest (all
# features) are trained on the other four and scored on it. Prints one line per type and model
# and draws docs/roc_person3d_TYPE.png. Usage: scripts/classifier-loso.sh [build-dir] [work-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
bin="$(pwd)/${1:-build}/bin/pedtrack"
work="${2:-out/classifier-loso}"
mkdir -p "$work"
types="classify_scene street_moving park_static plaza_groups parking_static"
for t in $types; do
  [ -s "$work/s_$t.csv" ] && continue
  {
    printf '[dataset]\npipeline = %s/configs/people_3d_vlp16.ini\nframe_step = 5\nmin_range = 1\n' "$(pwd)"
    printf 'max_range = 20\n'
    for seed in 601 602 603; do
      printf '[sim.s%s]\nscenario = %s/configs/scenarios/%s.ini\nseed = %s\n' "$seed" "$(pwd)" "$t" "$seed"
    done
  } > "$work/ds_$t.ini"
  "$bin" eval --model models/person3d_knn.yml --dataset "$work/ds_$t.ini" \
    --save-samples "$work/s_$t.csv" -q > /dev/null
done
for t in $types; do
  first=1
  for u in $types; do
    [ "$u" = "$t" ] && continue
    if [ $first = 1 ]; then cat "$work/s_$u.csv"; first=0; else tail -n +2 "$work/s_$u.csv"; fi
  done > "$work/train_without_$t.csv"
  "$bin" train knn --samples "$work/train_without_$t.csv" --features "h w d v lambda rho" \
    --out "$work/knn_$t.yml" -q > /dev/null
  "$bin" train svm --samples "$work/train_without_$t.csv" --out "$work/svm_$t.yml" -q > /dev/null
  "$bin" train forest --samples "$work/train_without_$t.csv" --out "$work/forest_$t.yml" -q \
    > /dev/null
  "$bin" eval --model "$work/knn_$t.yml" --model "$work/svm_$t.yml" --model "$work/forest_$t.yml" \
    --samples "$work/s_$t.csv" --at-fp 0.03 --at-detection 0.97 --roc "docs/roc_person3d_$t.png" \
    --json -q | python3 -c "
import json, sys
d = json.load(sys.stdin)
for m in d['models']:
    print('%-15s %-6s persons %5d non-persons %5d  AUC %.3f  detected at <= 3%% FP %.3f  FP at >= 97%% detected %.3f' % (
        '$t', m['kind'], d['persons'], d['nonpersons'], m['auc'], m['detection_rate_at_fp'],
        m['false_positive_rate_at_detection']))"
done
