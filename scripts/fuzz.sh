#!/usr/bin/env bash
# Builds the libFuzzer targets of test/fuzz/ (clang, ASan + UBSan, in build-fuzz/, apart from the
# colcon build) and runs each one from its seed corpus, test/fuzz/corpus/<target>/.
#   scripts/fuzz.sh --short         each target for a fixed number of executions (the CI's step)
#   scripts/fuzz.sh [--max-time S]  each target for the issue's budget: 10^7 executions or S
#                                   seconds (default 1800), whichever comes first, then a table
#   ... [TARGET...]                 only these targets (fuzz_read_png ...)
# Inputs that grow coverage go to build-fuzz/corpus/<target>/, never into the seeds. A finding (a
# crash, a sanitizer report, a leak, a timeout) leaves its reproducer in
# build-fuzz/findings/<target>/ (until the target's next run) and makes the script exit 1 naming it; replay it with
# build-fuzz/<target> FILE (test/fuzz/README.md).
set -euo pipefail
. "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$SR_ROOT"

# 5000 executions a target: the 16 targets take 22 s together on an idle 2-core machine and 53 s
# with both cores busy (the YAML readers' target is most of it); the first build takes 4 minutes
# (7 on a busy machine), a rebuild seconds.
short_runs=5000
long_runs=10000000
max_time=1800
short=false
targets=()
while [ $# -gt 0 ]; do
  case $1 in
    --short) short=true ;;
    --max-time) max_time=$2; shift ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1") ;;
  esac
  shift
done

build=$SR_ROOT/build-fuzz
build_fuzz_targets() {
  cmake -S test/fuzz -B "$build" -DCMAKE_CXX_COMPILER=clang++ > "$build/configure.log" 2>&1 \
    || { cat "$build/configure.log"; return 1; }
  make -C "$build" -j2 --no-print-directory fuzz_targets > "$build/make.log" 2>&1 || { tail -40 "$build/make.log"; return 1; }
}
mkdir -p "$build"
sr_step "build the fuzz targets (clang, ASan + UBSan, build-fuzz/)" build_fuzz_targets
if [ ${#targets[@]} -eq 0 ]; then
  for source in test/fuzz/fuzz_*.cpp; do targets+=("$(basename "$source" .cpp)"); done
fi

if $short; then
  budget=(-runs=$short_runs)
else
  budget=(-runs=$long_runs -max_total_time="$max_time")
fi
failed=()
table=$(printf '%-32s %12s %9s %9s' target executions seconds findings)
for target in "${targets[@]}"; do
  corpus=$build/corpus/$target findings=$build/findings/$target log=$build/logs/$target.log
  mkdir -p "$corpus" "$findings" "$build/logs"
  rm -f "$findings"/*  # a run's reproducers are its own
  start=$SECONDS rc=0
  # -timeout: any one input slower than 10 s is a finding too (a hang, not a fuzzer's slowness).
  "$build/$target" "${budget[@]}" -timeout=10 -print_final_stats=1 -artifact_prefix="$findings/" \
    "$corpus" "test/fuzz/corpus/$target" > "$log" 2>&1 || rc=$?
  seconds=$((SECONDS - start))
  executions=$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+)/\1/p' "$log" | tail -1)
  reproducers=$(find "$findings" -type f)
  count=$(echo -n "$reproducers" | grep -c . || true)
  if [ "$rc" -ne 0 ] && [ "$count" -eq 0 ]; then count=1; fi
  table+=$'\n'$(printf '%-32s %12s %9s %9s' "$target" "${executions:-?}" "$seconds" "$count")
  if [ "$count" -ne 0 ]; then
    sr_log "FINDING in $target (exit $rc): ${reproducers:-no reproducer written}; log: ${log#"$SR_ROOT"/}"
    grep -m3 -E 'ERROR: |runtime error|uncaught exception|terminate called' "$log" || true
    failed+=("$target")
  fi
done
echo "$table"
if [ ${#failed[@]} -ne 0 ]; then
  sr_log "FAILED: findings in ${failed[*]}"; exit 1
fi
sr_log "OK: ${#targets[@]} targets, no findings"
