#!/usr/bin/env bash
# Runs woven's libFuzzer targets (fuzz/, docs/FUZZING.md) one at a time, each for SECONDS (or a
# fixed number of executions, --runs), and prints a table of executions, coverage and time per target.
#
#   tools/fuzz.sh [--build-dir DIR] [--ctest] [--runs N] [TARGET|all] [SECONDS]
#
# TARGET is gltf, scene_file, wif, image, exr, bsdf_eval, options or converge (default all); SECONDS per target
# (default 60). --runs N: N executions instead, the same work on any machine, however fast.
# Build first: cmake --preset fuzz && cmake --build --preset fuzz.
# The corpus grows in DIR/corpus/TARGET and is kept between runs (the seeds in
# DIR/fuzz/seeds/TARGET are read too); crashing inputs go to DIR/artifacts/TARGET/, the log to
# DIR/logs/TARGET.log. --ctest (the CTest runs) starts from the seeds alone with a fixed
# seed, in DIR/ctest-corpus/TARGET, so a failure repeats.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-fuzz ctest=0 runs=
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --build-dir) build=$2; shift 2 ;;
    --ctest) ctest=1; shift ;;
    --runs) runs=$2; shift 2 ;;
    *) echo "usage: $0 [--build-dir DIR] [--ctest] [--runs N] [TARGET|all] [SECONDS]" >&2; exit 2 ;;
  esac
done
all=(gltf scene_file wif image exr bsdf_eval options converge)
which=${1:-all} seconds=${2:-60}
if [[ $which == all ]]; then targets=("${all[@]}"); else targets=("$which"); fi
[[ $seconds =~ ^[1-9][0-9]*$ ]] || { echo "$0: SECONDS must be a positive integer, not '$seconds'" >&2; exit 2; }
[[ -z $runs || $runs =~ ^[1-9][0-9]*$ ]] || { echo "$0: --runs must be a positive integer, not '$runs'" >&2; exit 2; }

# Limits: any single input taking 10 s is a hang; 2 GiB of memory, or one allocation that
# large, from inputs of a few kilobytes means a size was allocated before it was checked (the
# fuzz build lowers the one documented limit above it, images' decoded bytes: docs/FUZZING.md).
flags=(-rss_limit_mb=2048 -timeout=10 -print_final_stats=1)
if [[ -n $runs ]]; then flags+=(-runs="$runs"); else flags+=(-max_total_time="$seconds"); fi
# Leaks outside woven are suppressed by name (tools/lsan-suppressions.txt), which needs full
# stacks through libstdc++.
export LSAN_OPTIONS="suppressions=$PWD/tools/lsan-suppressions.txt:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export ASAN_OPTIONS="fast_unwind_on_malloc=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"

rows=() failed=0 budget="$seconds s"
[[ -n $runs ]] && budget="$runs runs"
for t in "${targets[@]}"; do
  exe=$build/fuzz/fuzz_$t seeds=$build/fuzz/seeds/$t
  [[ -x $exe && -d $seeds ]] || { echo "$0: no $exe or $seeds: cmake --build --preset fuzz first" >&2; exit 2; }
  if [[ $ctest == 1 ]]; then
    corpus=$build/ctest-corpus/$t
    rm -rf "$corpus"
    run_flags=(-seed=1)
  else
    corpus=$build/corpus/$t
    run_flags=()
  fi
  artifacts=$build/artifacts/$t log=$build/logs/$t.log
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  echo "fuzz_$t: $budget, corpus $corpus, log $log" >&2
  start=$(date +%s)
  status=ok
  "$exe" "${flags[@]}" "${run_flags[@]}" -artifact_prefix="$artifacts/" "$corpus" "$seeds" >"$log" 2>&1 || status=FAILED
  elapsed=$(( $(date +%s) - start ))
  # The last status line ("#N DONE cov: C ft: F corp: ...") and the final statistics.
  last=$(grep -E '^#[0-9]+' "$log" | tail -n 1 || true)
  cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$last")
  ft=$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$last")
  corp=$(sed -nE 's/.* corp: ([^ ]+).*/\1/p' <<<"$last")
  execs=$(sed -nE 's/^stat::number_of_executed_units: +([0-9]+)/\1/p' "$log")
  rate=$(sed -nE 's/^stat::average_exec_per_sec: +([0-9]+)/\1/p' "$log")
  rss=$(sed -nE 's/^stat::peak_rss_mb: +([0-9]+)/\1/p' "$log")
  if [[ $status != ok ]]; then
    failed=1
    echo "fuzz_$t FAILED; the end of $log:" >&2
    tail -n 40 "$log" >&2
  fi
  rows+=("$t ${elapsed} ${execs:--} ${rate:--} ${cov:--} ${ft:--} ${corp:--} ${rss:--} $status")
done

printf '\n%-11s %8s %12s %8s %7s %7s %12s %8s  %s\n' target "time s" executions "exec/s" cov ft "corpus" "rss MB" result
for r in "${rows[@]}"; do
  # shellcheck disable=SC2086
  printf '%-11s %8s %12s %8s %7s %7s %12s %8s  %s\n' $r
done
exit $failed
