#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A private single-node Slurm cluster on this machine, for the tests of scripts/slurm/ and for
# measuring them. Its own munge key and socket, its own ports, configuration, state
# and logs, all in one temporary folder: a system Slurm or munge, if any, is neither used nor
# touched. Every daemon it starts is stopped when it ends, also on failure or interrupt.
#
#   tests/slurm/cluster.sh run -- COMMAND [ARGS...]
#       starts the cluster, runs COMMAND with SLURM_CONF (and PATH) set for sbatch, squeue and
#       scontrol, stops the cluster, and exits with COMMAND's status. A watchdog stops it too
#       should this script be killed outright (SIGKILL).
#
# Needs root (slurmd runs jobs as their user; CI runs as root) and slurmctld, slurmd, munged,
# mungekey, sbatch, squeue and scontrol (Debian: slurm-wlm, munge). Exits 77, naming what is
# missing, where it cannot run; 1 when the cluster does not come up (its logs are printed).
set -euo pipefail

skip() {
    echo "SKIPPED: $*"
    exit 77
}

require_cluster_tools() {
    local missing=()
    for tool in slurmctld slurmd munged mungekey sbatch squeue scontrol; do
        command -v "$tool" >/dev/null 2>&1 || PATH="$PATH:/usr/sbin:/sbin" command -v "$tool" >/dev/null 2>&1 ||
            missing+=("$tool")
    done
    [ ${#missing[@]} -eq 0 ] || skip "${missing[*]} not installed (Debian packages slurm-wlm and munge)"
    [ "$(id -u)" -eq 0 ] || skip "a private Slurm cluster needs root (slurmd starts jobs as their user); running as $(id -un)"
}

# A TCP port nobody listens on, from a range away from Slurm's defaults (6817-6819)
free_port() {
    local port
    for _ in $(seq 100); do
        port=$((20000 + RANDOM % 20000))
        if ! ss -Htln "sport = :$port" 2>/dev/null | grep -q . && [ "$port" != "${1:-}" ]; then
            echo "$port"
            return
        fi
    done
    echo "cluster.sh: no free TCP port found" >&2
    return 1
}

CLUSTER_DIR=""

# The processes descended from `pid`, deepest first
descendants() {
    local child
    for child in $(ps -o pid= --ppid "$1" 2>/dev/null); do
        descendants "$child"
        echo "$child"
    done
}

stop_cluster() {
    local pid
    # Jobs first, through Slurm, so their steps end cleanly
    if [ -n "$CLUSTER_DIR" ] && [ -f "$CLUSTER_DIR/slurmctld.pid" ]; then
        SLURM_CONF="$CLUSTER_DIR/slurm.conf" scancel --quiet --partition=test 2>/dev/null || true
        for _ in $(seq 50); do
            [ -z "$(SLURM_CONF="$CLUSTER_DIR/slurm.conf" squeue -h -o %i 2>/dev/null)" ] && break
            sleep 0.2
        done
    fi
    # slurmd first (it ends the job steps it runs), then the controller, then munge
    for name in slurmd slurmctld munged; do
        if [ -z "$CLUSTER_DIR" ] || [ ! -f "$CLUSTER_DIR/$name.pid" ]; then continue; fi
        pid=$(cat "$CLUSTER_DIR/$name.pid" 2>/dev/null || true)
        [ -n "$pid" ] || continue
        kill "$pid" 2>/dev/null || continue
        for _ in $(seq 50); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.1
        done
        kill -9 "$pid" 2>/dev/null || true
    done
    # Job steps that outlived their slurmd: this cluster's slurmstepd (its configuration in
    # their environment) and what they started
    if [ -n "$CLUSTER_DIR" ]; then
        for pid in $(pgrep -x slurmstepd 2>/dev/null || true); do
            if tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "SLURM_CONF=$CLUSTER_DIR/slurm.conf"; then
                for victim in $(descendants "$pid") "$pid"; do kill -9 "$victim" 2>/dev/null || true; done
            fi
        done
        rm -rf "$CLUSTER_DIR"
    fi
    CLUSTER_DIR=""
}

print_logs() {
    for log in "$CLUSTER_DIR"/log/*.log; do
        [ -f "$log" ] || continue
        echo "--- $log (last 30 lines)"
        tail -n 30 "$log"
    done
}

start_cluster() {
    PATH="$PATH:/usr/sbin:/sbin"
    CLUSTER_DIR=$(mktemp -d "${TMPDIR:-/tmp}/scadray-slurm.XXXXXX")
    chmod 700 "$CLUSTER_DIR"
    local d=$CLUSTER_DIR
    mkdir -p "$d/munge" "$d/state" "$d/spool" "$d/log"
    chmod 700 "$d/munge"

    # munge: a key of its own and a socket in the cluster's folder
    mungekey --create --keyfile="$d/munge/munge.key" >/dev/null
    chmod 400 "$d/munge/munge.key"
    munged --force --socket="$d/munge/munge.socket" --key-file="$d/munge/munge.key" \
        --pid-file="$d/munged.pid" --log-file="$d/log/munged.log" --seed-file="$d/munge/seed"

    local ctld_port slurmd_port cpus memory host
    ctld_port=$(free_port)
    slurmd_port=$(free_port "$ctld_port")
    cpus=$(nproc)
    memory=$(($(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2))
    host=$(hostname -s)
    cat >"$d/slurm.conf" <<EOF
# A private single-node cluster (tests/slurm/cluster.sh)
ClusterName=scadraytest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$d/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/slurmctld.pid
SlurmdPidFile=$d/slurmd.pid
SlurmctldLogFile=$d/log/slurmctld.log
SlurmdLogFile=$d/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
PlugStackConfig=$d/plugstack.conf
# No cgroups: process tracking by the process tree, no task containment, no accounting
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
# Finished jobs stay visible to scontrol for a while; the test reads their exit state
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
EOF
    cat >"$d/cgroup.conf" <<EOF
# Nothing is confined to cgroups in this cluster (ProctrackType=proctrack/linuxproc)
CgroupPlugin=autodetect
IgnoreSystemd=yes
ConstrainCores=no
ConstrainRAMSpace=no
EOF
    : >"$d/plugstack.conf"
    export SLURM_CONF="$d/slurm.conf"
    # A watchdog in a session of its own stops the cluster should this shell be killed past its
    # traps (SIGKILL from a test driver's timeout)
    setsid bash "${BASH_SOURCE[0]}" watch "$$" "$d" </dev/null >/dev/null 2>&1 &

    slurmctld -f "$SLURM_CONF" -i
    slurmd -f "$SLURM_CONF" -N "$host"
    # Up when the node is idle
    local state=""
    for _ in $(seq 150); do
        state=$(sinfo -h -N -o '%t' 2>/dev/null | head -n 1 || true)
        [ "$state" = "idle" ] && return 0
        sleep 0.2
    done
    echo "cluster.sh: the cluster did not come up (node state '$state')" >&2
    print_logs >&2
    return 1
}

main() {
    # Internal: watch PID DIR stops the cluster in DIR once process PID has gone
    if [ "${1:-}" = "watch" ] && [ $# -eq 3 ]; then
        while kill -0 "$2" 2>/dev/null && [ -d "$3" ]; do sleep 2; done
        [ -d "$3" ] || exit 0
        CLUSTER_DIR=$3
        stop_cluster
        exit 0
    fi
    if [ "${1:-}" != "run" ] || [ "${2:-}" != "--" ] || [ $# -lt 3 ]; then
        echo "usage: $0 run -- COMMAND [ARGS...]" >&2
        exit 2
    fi
    shift 2
    require_cluster_tools
    trap stop_cluster EXIT
    trap 'exit 130' INT TERM
    start_cluster || exit 1
    local rc=0
    "$@" || rc=$?
    if [ "$rc" -ne 0 ] && [ "$rc" -ne 77 ]; then print_logs >&2; fi
    exit "$rc"
}

if [ "${BASH_SOURCE[0]}" = "$0" ]; then main "$@"; fi
