#!/usr/bin/env bash
# Runs every shipped pipeline (configs/*.ini) on its default input with two checkouts of pedtrack
# and compares what each wrote, byte for byte: a refactoring must leave every output as it was.
#
#   scripts/compare-outputs.sh OLD_CHECKOUT NEW_CHECKOUT [WORK_DIR]
#
# Each checkout runs its own configs/ with its own build (CHECKOUT/build/bin/pedtrack, or
# OLD_BUILD / NEW_BUILD: a build directory; each finds the plugins of its own build tree), e.g.
#   git worktree add ../before HEAD~3 && cmake -S ../before -B ../before/build && \
#     cmake --build ../before/build -j2 && scripts/compare-outputs.sh ../before .
# Every file of each run's --out folder is compared except run.json,
# whose timings differ from run to run; run.json is compared with its timing fields removed.
# Pipelines that need a device are skipped; those that need the leg_tracker data run when
# PEDTRACK_DATA (by default the data folder next to the checkout) holds it. One more run covers
# what users run most: the leg pipeline on the leg_tracker demo bag (negative_2_merged.ini is the
# moving robot without odometry: scan matching). ONLY=REGEX runs just the pipelines whose name
# matches. Prints one line per pipeline; exit 1 when any output differs.
set -uo pipefail
old_root=$(realpath "$1") new_root=$(realpath "$2")
old=$(realpath "${OLD_BUILD:-$old_root/build}")/bin/pedtrack
new=$(realpath "${NEW_BUILD:-$new_root/build}")/bin/pedtrack
root=$new_root
work=${3:-$(mktemp -d /tmp/pedtrack-compare.XXXXXX)}
export PEDTRACK_DATA=${PEDTRACK_DATA:-$(cd "$root/.." && pwd)/shared/data}
mkdir -p "$work"

# name | pipeline | extra arguments
cases=()
for cfg in "$root"/configs/*.ini; do
  cases+=("$(basename "$cfg" .ini)|$cfg|")
done
demo=$PEDTRACK_DATA/leg_tracker/demo_stationary_simple_environment.bag
cases+=("people_2d_legs+demo_bag|$root/configs/people_2d_legs.ini|--input $demo")

# run.json without what changes from run to run or between checkouts (times, dates, the machine,
# the version, the checkout's own path).
strip_json() {
  python3 - "$1" "$2" <<'EOF'
import json, sys
root = sys.argv[2]
def clean(v):
    if isinstance(v, dict):
        return {k: clean(x) for k, x in v.items()
                if k not in ("api_version", "pedtrack_version") and
                not any(s in k for s in ("ms", "time", "seconds", "date", "latency",
                                         "per_s", "rss", "host", "commit"))}
    if isinstance(v, list):
        return [clean(x) for x in v]
    if isinstance(v, str):
        return v.replace(root, "ROOT")
    return v
print(json.dumps(clean(json.load(open(sys.argv[1]))), indent=1, sort_keys=True))
EOF
}

status=0
for c in "${cases[@]}"; do
  IFS='|' read -r name cfg extra <<<"$c"
  [[ -z ${ONLY:-} || $name =~ $ONLY ]] || continue  # ONLY=REGEX: just these pipelines
  if grep -qE '^\s*plugin\s*=\s*mrpt_sensor' "$cfg"; then
    echo "skipped   $name (needs a device)"
    continue
  fi
  if grep -q 'PEDTRACK_DATA' "$cfg" || [[ $extra == *"$PEDTRACK_DATA"* ]]; then
    if [ ! -d "$PEDTRACK_DATA/leg_tracker" ]; then
      echo "skipped   $name (no $PEDTRACK_DATA/leg_tracker)"
      continue
    fi
  fi
  if [ ! -f "$old_root/configs/$(basename "$cfg")" ]; then
    echo "new       $name (no such pipeline in $old_root)"
    continue
  fi
  for side in old new; do
    bin=${!side}
    side_root=${side}_root
    rm -rf "${work:?}/$side/$name"
    mkdir -p "$work/$side"
    # shellcheck disable=SC2086
    "$bin" run "${!side_root}/configs/$(basename "$cfg")" $extra --out "$work/$side/$name" -q \
      >"$work/$side.$name.log" 2>&1
    echo $? >"$work/$side/$name.exit"
  done
  diffs=()
  [ "$(cat "$work/old/$name.exit")" = "$(cat "$work/new/$name.exit")" ] ||
    diffs+=("exit $(cat "$work/old/$name.exit") -> $(cat "$work/new/$name.exit")")
  files=$( (cd "$work/old/$name" 2>/dev/null && find . -type f; cd "$work/new/$name" 2>/dev/null &&
    find . -type f) | sort -u)
  for f in $files; do
    a=$work/old/$name/$f b=$work/new/$name/$f
    if [ ! -f "$a" ] || [ ! -f "$b" ]; then
      diffs+=("${f#./} only in one")
    elif [ "${f##*/}" = run.json ]; then
      cmp -s <(strip_json "$a" "$old_root") <(strip_json "$b" "$new_root") ||
        diffs+=("run.json (beyond timings)")
    else
      cmp -s "$a" "$b" || diffs+=("${f#./}")
    fi
  done
  n=$(echo "$files" | grep -c .)
  if [ ${#diffs[@]} -eq 0 ]; then
    echo "identical $name ($n files, $(wc -l <"$work/new/$name/tracks.csv" 2>/dev/null || echo 0) track rows)"
  else
    echo "DIFFERENT $name: ${diffs[*]}"
    status=1
  fi
done
echo "outputs in $work"
exit $status
