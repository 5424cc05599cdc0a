#!/bin/sh
# A private single-node Slurm cluster on this machine, for trying the sweep scripts and for
# the tests (tests/sweep/slurm.sh): munged on its own socket with a key made here, slurmctld and
# slurmd on two free TCP ports, every file (configuration, state, spool, logs) in DIR. No
# cgroups (proctrack/linuxproc, task/none); job start and end times in DIR/jobcomp.log.
# Needs root (the daemons run as root) and Debian's slurm-wlm and munge.
#
#   sh scripts/slurm/local-cluster.sh start DIR   # then: export SLURM_CONF=DIR/slurm.conf
#   sh scripts/slurm/local-cluster.sh stop DIR
#
# start exits 0 once the node takes jobs; otherwise it stops what it started, prints the
# daemons' logs and why on stderr, and exits 1.
# SPDX-License-Identifier: Apache-2.0
set -eu

# --- knobs ---------------------------------------------------------------------------------
NODE=tirenvnode        # the node's name (slurmd -N), not the host's
CPUS=${CPUS:-$(nproc)} # cores the node offers
WAIT=${WAIT:-60}       # seconds to wait for the daemons

usage() {
    echo "usage: $0 start|stop DIR" >&2
    exit 2
}
[ $# -eq 2 ] || usage
action=$1
dir=$2

stop() {
    for d in slurmd slurmctld munged; do
        if [ -s "$dir/$d.pid" ]; then
            pid=$(cat "$dir/$d.pid")
            kill "$pid" 2>/dev/null || true
            # Wait for it to go (a daemon holding its port would fail the next start).
            i=0
            while kill -0 "$pid" 2>/dev/null && [ $i -lt 100 ]; do
                sleep 0.1
                i=$((i + 1))
            done
            kill -9 "$pid" 2>/dev/null || true
            rm -f "$dir/$d.pid"
        fi
    done
}

fail() {
    echo "local-cluster: $*" >&2
    for log in munged.log slurmctld.log slurmd.log; do
        if [ -s "$dir/$log" ]; then
            echo "--- $dir/$log (last lines)" >&2
            tail -n 15 "$dir/$log" >&2
        fi
    done
    stop
    exit 1
}

# Two TCP ports nothing listens on: the listening ports from /proc/net/tcp{,6} (hex), and
# candidates from a range seeded by the process id, so that two runs at once differ.
free_ports() {
    used=$(cat /proc/net/tcp /proc/net/tcp6 2>/dev/null |
           awk 'NR > 1 && $4 == "0A" { split($2, a, ":"); print a[2] }' | sort -u)
    port=$((20000 + ($$ * 7) % 30000))
    found=""
    n=0
    while [ $n -lt 2 ]; do
        hex=$(printf '%04X' "$port")
        if ! echo "$used" | grep -qx "$hex"; then
            found="$found $port"
            n=$((n + 1))
        fi
        port=$((port + 1))
    done
    echo "$found"
}

start() {
    [ "$(id -u)" -eq 0 ] || fail "needs root: the Slurm and munge daemons run as root here"
    for p in munged munge slurmctld slurmd sbatch scontrol sinfo; do
        command -v "$p" >/dev/null 2>&1 ||
            fail "$p not found: install Debian's slurm-wlm and munge (scripts/deps.sh --slurm)"
    done
    mkdir -p "$dir/state" "$dir/spool"
    dir=$(cd "$dir" && pwd)
    chmod 711 "$dir"  # munged needs its socket's directory searchable by all
    # The key: 1 KiB of randomness, readable by its owner only (munged checks).
    rm -f "$dir/munge.key"
    dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 2>/dev/null
    chmod 400 "$dir/munge.key"
    munged --force --key-file="$dir/munge.key" --socket="$dir/munge.sock" \
        --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" \
        --seed-file="$dir/munged.seed" || fail "munged did not start"
    i=0
    until munge -S "$dir/munge.sock" -n 2>/dev/null | unmunge -S "$dir/munge.sock" \
            >/dev/null 2>&1; do
        i=$((i + 1))
        [ $i -lt $((WAIT * 10)) ] || fail "munged does not answer on $dir/munge.sock"
        sleep 0.1
    done

    set -- $(free_ports)
    cat >"$dir/slurm.conf" <<CONF
# A single-node cluster made by scripts/slurm/local-cluster.sh; everything lives in $dir.
ClusterName=tirenvlocal
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$1
SlurmdPort=$2
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge.sock
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
# No cgroups: processes tracked through /proc, tasks not bound.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
# Job start and end times without an accounting database (sacct needs slurmdbd).
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.log
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=$NODE NodeHostname=localhost NodeAddr=127.0.0.1 CPUs=$CPUS State=UNKNOWN
PartitionName=local Nodes=$NODE Default=YES MaxTime=INFINITE State=UP
CONF
    export SLURM_CONF="$dir/slurm.conf"
    slurmctld -f "$SLURM_CONF" -c || fail "slurmctld did not start"
    slurmd -f "$SLURM_CONF" -N "$NODE" || fail "slurmd did not start"
    i=0
    until [ "$(sinfo -h -n "$NODE" -o %T 2>/dev/null)" = idle ]; do
        i=$((i + 1))
        [ $i -lt $((WAIT * 10)) ] ||
            fail "the node is not idle after $WAIT s (sinfo: $(sinfo -h 2>&1 | head -n 1))"
        sleep 0.1
    done
    echo "local-cluster: up: node $NODE, $CPUS CPUs, ports $1 and $2; export SLURM_CONF=$SLURM_CONF" >&2
}

case $action in
start) start ;;
stop) stop ;;
*) usage ;;
esac
