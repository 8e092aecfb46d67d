#!/usr/bin/env bash
# The default job (README "Quick start"): installs what a fresh Debian bookworm machine lacks,
# builds Release into build/, then simulates a crowd of 20 people seen by a VLP-16
# (configs/scenarios/crowd.ini), tracks it with the complete 3D pipeline
# (configs/people_3d_vlp16.ini), scores the tracks against the simulated truth and draws frame
# 150 to out/crowd/crowd.png. No external files are needed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j2
bin=build/bin/pedtrack
out=out/crowd
"$bin" sim configs/scenarios/crowd.ini --out "$out"
"$bin" run configs/people_3d_vlp16.ini --input "$out/sim.rawlog" --out "$out/tracks"
"$bin" eval --truth "$out/truth.csv" --tracks "$out/tracks/tracks.csv"
"$bin" render --rawlog "$out/sim.rawlog" --run "$out/tracks" --truth "$out/truth.csv" \
  --frame 150 --center 10,0 --range 10 --out "$out/crowd.png"
echo "demo: tracks in $out/tracks/tracks.csv, picture in $out/crowd.png"
