#!/usr/bin/env bash
# The project's test command (README "Quick start"; .ci/run runs exactly this):
#   1. builds everything with clang under AddressSanitizer + UndefinedBehaviorSanitizer (and
#      libFuzzer's coverage) in build-check/, and runs the whole test suite there;
#   2. builds Release in build/ (the host, the plugins and the tests labelled `full_length`) and
#      runs there what the sanitized suite shortens or skips (the timing suite `bench --suite
#      --quick`, the fault matrix, every scenario simulated whole, the classifier, segmentation,
#      leg and shape pipelines and the papers' figures at full length);
#   3. runs every libFuzzer target for a bounded time (scripts/fuzz.sh);
# and prints how long each step took. Any sanitizer report, failed test or fuzzer crash fails it.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
build=${PEDTRACK_CHECK_BUILD:-build-check}
release=${PEDTRACK_RELEASE_BUILD:-build}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:detect_odr_violation=0}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/scripts/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# Both builds compile each target's sources in batches of 8 (CMake's unity build: the headers and
# the Eigen and MRPT templates each batch shares are compiled once, not once per file; a cold
# build takes about a third less) and link with lld where it is installed. CI starts cold.
fast_build=(-DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=8)
if command -v ld.lld > /dev/null; then
  for kind in EXE SHARED MODULE; do fast_build+=("-DCMAKE_${kind}_LINKER_FLAGS=-fuse-ld=lld"); done
fi
times=()
step() {  # step NAME COMMAND...
  local name=$1 start
  shift
  start=$(date +%s)
  echo "== $name"
  "$@"
  times+=("$name: $(( $(date +%s) - start )) s")
}
step "build (clang, ASan + UBSan + fuzzer coverage)" bash -c \
  "CC=clang CXX=clang++ cmake -S . -B '$build' -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS=-O1 \
     -DPEDTRACK_SANITIZE=ON -DPEDTRACK_FUZZ=ON ${fast_build[*]} > /dev/null \
   && cmake --build '$build' -j2"
step "test suite under ASan + UBSan" ctest --test-dir "$build" -j2 --output-on-failure -LE live
# Tests against live devices on loopback (label `live`) get up to three attempts: what a device
# streaming at its own pace delivers depends on how the host schedules the reader (a VM's CPU
# steal lost whole VLP-16 revolutions). A test that fails three times still fails the run.
step "live-device tests under ASan + UBSan" ctest --test-dir "$build" --output-on-failure -L live \
  --repeat until-pass:3
# Release builds what the full-length tests run (the host, the plugins and those tests' own
# executables): the other tests ran above.
step "build (Release)" bash -c \
  "cmake -S . -B '$release' -DCMAKE_BUILD_TYPE=Release ${fast_build[*]} > /dev/null \
   && cmake --build '$release' -j2 --target full_length_tests"
step "full-length tests (Release)" ctest --test-dir "$release" -j2 --output-on-failure \
  -L full_length
export PEDTRACK_FUZZ_SECONDS=${PEDTRACK_FUZZ_SECONDS:-12}
step "fuzzing ($PEDTRACK_FUZZ_SECONDS s per target)" scripts/fuzz.sh "$build"
echo "== times"
printf '  %s\n' "${times[@]}"
