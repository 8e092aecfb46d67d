#!/usr/bin/env bash
# Rebuilds every model under models/ that the shipped configs use, from the dataset files in
# configs/training/. Deterministic (fixed seeds). The leg models need leg_tracker's bags:
# PEDTRACK_DATA (the folder holding leg_tracker/; by default the data folder next to the
# checkout). Usage: scripts/train-models.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
bin="${1:-build}/bin/pedtrack"
export PEDTRACK_DATA="${PEDTRACK_DATA:-$(cd .. && pwd)/shared/data}"
t=configs/training
"$bin" train knn "$t/person3d_train.ini" --out models/person3d_knn.yml -q
"$bin" train svm "$t/person3d_train.ini" --out models/person3d_svm.yml -q
"$bin" train svm "$t/torso_train.ini" --out models/torso_svm.yml -q
"$bin" train knn "$t/torso_train.ini" --out models/torso_knn.yml -q
"$bin" train forest "$t/person3d_forest_train.ini" --out models/person3d_forest.yml -q
gzip -f models/person3d_forest.yml
if [ -d "$PEDTRACK_DATA/leg_tracker" ]; then
  "$bin" train knn "$t/legs_train.ini" --out models/legs_knn.yml -q
  "$bin" train svm "$t/legs_train.ini" --out models/legs_svm.yml -q
else
  echo "train-models: $PEDTRACK_DATA/leg_tracker not found: leg models not rebuilt" >&2
fi
