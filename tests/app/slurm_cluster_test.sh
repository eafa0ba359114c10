#!/usr/bin/env bash
# woven submit on a real one-node Slurm cluster, started and stopped here with the project's
# tools/slurm scripts:
#   1. a frame submitted as 4 tasks, --wait, equals a local render bit for bit;
#   2. a task killed with scancel makes --wait fail, the merge refuse and name the task's
#      samples, and the parts there are go to OUT.partial.exr, never to OUT;
#   3. the killed task requeued (scontrol requeue) renders the same samples again: merging then
#      gives the local frame bit for bit, no sample twice;
#   4. --wait gives up after --wait-timeout.
# Every wait is bounded, and the EXIT trap stops the daemons by their pid files whatever fails.
# Exits 77 (skipped) when Slurm or munge is not installed, or not run as root.
#
#   slurm_cluster_test.sh WOVEN EXR_EQUAL SOURCE_DIR
set -euo pipefail

woven=$1 exr_equal=$2 source=$3
export PATH=$PATH:/usr/sbin
for program in slurmctld slurmd munged mungekey sbatch squeue scontrol scancel; do
  command -v "$program" >/dev/null || { echo "SKIP: $program is not installed (tools/install-deps.sh installs slurm-wlm and munge)"; exit 77; }
done
[ "$(id -u)" -eq 0 ] || { echo "SKIP: starting slurmd needs root"; exit 77; }

work=$(mktemp -d /tmp/woven-slurm-test.XXXXXX)
chmod 755 "$work"  # the munge user enters it
submit_pid=
cleanup() {
  [ -z "$submit_pid" ] || kill "$submit_pid" 2>/dev/null || true
  "$source/tools/slurm/stop_cluster.sh" "$work/cluster" || true
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 143' TERM INT

fail() { echo "FAIL: $*" >&2; exit 1; }
# wait_until SECONDS COMMAND...: runs COMMAND every 0.2 s until it succeeds; fails after SECONDS.
wait_until() {
  local deadline=$((SECONDS + $1)); shift
  until "$@"; do
    ((SECONDS < deadline)) || fail "timed out waiting for: $*"
    sleep 0.2
  done
}

"$source/tools/slurm/start_cluster.sh" "$work/cluster" 30
export SLURM_CONF=$work/cluster/slurm.conf
scene=$source/assets/default_scene.json

echo "== 1. four tasks merge to the local frame"
small=(--width 64 --height 48 --spp 8 --integrator bdpt --seed 5)
"$woven" render "$scene" "${small[@]}" -o "$work/local.exr" >/dev/null 2>&1
"$woven" submit "$scene" "${small[@]}" --tasks 4 -o "$work/one/frame.exr" --wait --wait-timeout 60 ||
  fail "woven submit --wait failed"
"$exr_equal" "$work/local.exr" "$work/one/frame.exr" || fail "the merged frame differs from the local render"
ls "$work/one/frame.slurm/logs/"render_*_3.log >/dev/null || fail "no log of render task 3"

echo "== 2. a task killed with scancel: the merge refuses and names its samples"
# Tasks of a few seconds, so task 1 is still running when it is killed.
large=(--width 640 --height 480 --spp 16 --integrator bdpt --seed 6)
out=$work/two/frame.exr
"$woven" submit "$scene" "${large[@]}" --tasks 4 -o "$out" --wait --wait-timeout 90 >"$work/submit.out" 2>"$work/submit.err" &
submit_pid=$!
wait_until 20 grep -q '^render job' "$work/submit.out"
job=$(awk '/^render job/ { sub(":", "", $3); print $3; exit }' "$work/submit.out")
task_running() { [ "$(squeue --noheader --jobs="${job}_1" --format=%T 2>/dev/null)" = RUNNING ]; }
wait_until 30 task_running
scancel "${job}_1"
status=0
wait "$submit_pid" || status=$?
cat "$work/submit.out" "$work/submit.err"
[ "$status" -ne 0 ] || fail "woven submit --wait succeeded although task ${job}_1 was cancelled"
grep -q "render task ${job}_1 (.*samples 4-7) CANCELLED" "$work/submit.err" || fail "the cancelled task is not named"
grep -q "frame.exr not written: samples 4-7 missing" "$work/submit.err" || fail "the merge does not name the missing samples"
[ ! -e "$out" ] || fail "$out was written although samples were missing"
[ -f "$work/two/frame.partial.exr" ] || fail "no partial frame"

echo "== 3. the cancelled task requeued: no sample twice, the local frame again"
scontrol requeue "${job}_1"
scontrol update JobId="${job}_1" StartTime=now  # a requeued job otherwise waits two minutes
task_completed() { [ "$(squeue --noheader --states=all --jobs="${job}_1" --format=%T 2>/dev/null)" = COMPLETED ]; }
wait_until 60 task_completed
bash "$work/two/frame.slurm/merge.sbatch" || fail "the merge failed after the requeued task completed"
[ ! -e "$work/two/frame.partial.exr" ] || fail "the partial frame outlived the complete one"
"$woven" render "$scene" "${large[@]}" -o "$work/local_large.exr" >/dev/null 2>&1
"$exr_equal" "$work/local_large.exr" "$out" || fail "the frame with the requeued task differs from the local render"

echo "== 4. --wait gives up after --wait-timeout, and the jobs go on"
status=0
"$woven" submit "$scene" "${large[@]}" --tasks 4 -o "$work/three/frame.exr" --wait --wait-timeout 1 2>"$work/timeout.err" ||
  status=$?
[ "$status" -ne 0 ] || fail "woven submit --wait-timeout 1 succeeded"
grep -q "gave up waiting after 1 s; the jobs go on" "$work/timeout.err" || fail "no message on the timeout"
[ -n "$(squeue --noheader --states=pending,running)" ] || fail "the jobs did not go on"
echo "PASS"
