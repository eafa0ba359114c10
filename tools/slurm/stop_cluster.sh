#!/usr/bin/env bash
# Stops a cluster that tools/slurm/start_cluster.sh started in DIR: cancels its jobs (so no job
# step outlives slurmd), then ends slurmd, slurmctld and munged by the pid files in DIR, killing
# any that has not exited after TIMEOUT_SECONDS. Safe to run twice, or after a failed start.
#
#   tools/slurm/stop_cluster.sh DIR [TIMEOUT_SECONDS]
set -uo pipefail

dir=${1:?usage: stop_cluster.sh DIR [TIMEOUT_SECONDS]}
timeout=${2:-15}
export PATH=$PATH:/usr/sbin

# The pid in FILE if that process is still the daemon NAME (a pid file can outlive its process).
daemon_pid() {
  local file=$1 name=$2 pid
  [ -f "$file" ] || return 1
  pid=$(<"$file")
  [[ $pid =~ ^[0-9]+$ ]] && [ "$(cat /proc/"$pid"/comm 2>/dev/null)" = "$name" ] && echo "$pid"
}

if [ -f "$dir/slurm.conf" ] && daemon_pid "$dir/slurmctld.pid" slurmctld >/dev/null; then
  export SLURM_CONF=$dir/slurm.conf
  ids=$(timeout 5 squeue -h -o %A 2>/dev/null | sort -u)
  if [ -n "$ids" ]; then
    # shellcheck disable=SC2086
    timeout 5 scancel $ids 2>/dev/null
    deadline=$((SECONDS + timeout))
    while [ -n "$(timeout 5 squeue -h -t running,completing -o %A 2>/dev/null)" ] && ((SECONDS < deadline)); do sleep 0.2; done
  fi
fi

# All at once: each takes about two seconds to shut down.
pids=()
for daemon in slurmd slurmctld munge/munged; do
  pid=$(daemon_pid "$dir/$daemon.pid" "${daemon#*/}") && kill -TERM "$pid" 2>/dev/null && pids+=("$pid")
done
deadline=$((SECONDS + timeout))
status=0
for pid in "${pids[@]}"; do
  while kill -0 "$pid" 2>/dev/null && ((SECONDS < deadline)); do sleep 0.1; done
  if kill -0 "$pid" 2>/dev/null; then
    echo "stop_cluster.sh: $(cat /proc/"$pid"/comm 2>/dev/null) (pid $pid) did not exit in ${timeout} s: killing it" >&2
    kill -KILL "$pid" 2>/dev/null
    status=1
  fi
done
exit $status
