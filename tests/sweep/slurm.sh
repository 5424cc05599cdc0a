#!/bin/sh
# The Slurm scripts (scripts/slurm/) on a single-node cluster this test starts itself
# (scripts/slurm/local-cluster.sh): submit.sh submits the shards as a job array and the merge
# after them; the merged data set must equal one 'tirenv sweep' of the whole grid, byte for
# byte (diff -r). Prints the wall time from submission to the merged result and each job's
# time (from the cluster's job-completion log).
#   sh tests/sweep/slurm.sh BIN SOURCE_DIR
# Environment: SHARDS (default 4), CPUS per task (default 1), SWEEP_ARGS (default a small
# springs grid; tests/sweep/slurm.sh with the 200-case ring grid of submit.sh measures the figure
# in README.md).
# Exit 0 on success, 1 on failure, 77 (CTest's SKIP_RETURN_CODE) with a loud "SKIPPED: ..."
# line when Slurm cannot start here (not root, the packages missing, the daemons failing).
# SPDX-License-Identifier: Apache-2.0
set -u
bin=$1 src=$2
case $bin in /*) ;; *) bin=$PWD/$bin ;; esac
SHARDS=${SHARDS:-4}
CPUS=${CPUS:-1}
SWEEP_ARGS=${SWEEP_ARGS:---lengths 0.05,0.1,0.2 --heights 0.025,0.05,0.1 --contact-lengths 0.3,0.38 --set INTERRADIAL_STIFFNESS=8000,12000 --model springs --validation-fraction 0.2}
WAIT=${WAIT:-600}  # seconds for the jobs

skip() {
    echo "SKIPPED: slurm could not start because $*"
    echo "SKIPPED: (tests/sweep/slurm.sh; needs root and Debian's slurm-wlm and munge:"
    echo "SKIPPED:  sh scripts/deps.sh --slurm)"
    exit 77
}
[ "$(id -u)" -eq 0 ] || skip "this test is not root (the daemons run as root)"
for p in munged slurmctld slurmd sbatch; do
    command -v "$p" >/dev/null 2>&1 || skip "$p is not installed"
done

tmp=$(mktemp -d)
cluster=$tmp/cluster
trap 'sh "$src/scripts/slurm/local-cluster.sh" stop "$cluster" 2>/dev/null; rm -rf "$tmp"' EXIT
trap 'exit 2' INT TERM
if ! CPUS=2 sh "$src/scripts/slurm/local-cluster.sh" start "$cluster" 2>"$tmp/start.err"; then
    sed 's/^/# /' "$tmp/start.err"
    skip "$(grep '^local-cluster:' "$tmp/start.err" | head -n 1)"
fi
export SLURM_CONF=$cluster/slurm.conf

n=0 failed=0
check() {
    n=$((n + 1))
    if eval "$2"; then
        echo "ok $n - $1"
    else
        failed=$((failed + 1))
        echo "not ok $n - $1"
    fi
}

t0=$(date +%s.%N)
TIRENV=$bin OUT=$tmp/merged SHARDS=$SHARDS CPUS=$CPUS TIME=00:30:00 SWEEP_ARGS=$SWEEP_ARGS \
    sh "$src/scripts/slurm/submit.sh" >"$tmp/submit.out" 2>&1
rc=$?
sed 's/^/# /' "$tmp/submit.out"
check "submit.sh submits the shards and the merge" '[ $rc -eq 0 ]'
merge=$(awk '/^submitted:/ { for (i = 1; i < NF; ++i) if ($i == "merge" && $(i + 1) == "job") print $(i + 2) }' \
        "$tmp/submit.out")
array=$(awk '/^submitted:/ { print $4 }' "$tmp/submit.out")

# Until the merge job has left the queue (it runs after every shard).
i=0
while [ -n "$merge" ] && [ -n "$(squeue -h -j "$merge" 2>/dev/null)" ] && [ $i -lt $((WAIT * 5)) ]; do
    sleep 0.2
    i=$((i + 1))
done
t1=$(date +%s.%N)
for f in "$tmp"/merged.parts/*.log; do
    [ -f "$f" ] && { echo "# --- $f"; tail -n 3 "$f" | sed 's/^/#   /'; }
done
check "the merge job ran after the shards and succeeded" \
    'grep -q "JobId=$merge .*JobState=COMPLETED" "$cluster/jobcomp.log"'
check "every shard completed" \
    '[ "$(grep "JobState=COMPLETED" "$cluster/jobcomp.log" | grep -c "ArrayJobId=$array ")" -eq "$SHARDS" ]'

# shellcheck disable=SC2086 # the grid's options, split on purpose
t2=$(date +%s.%N)
"$bin" sweep $SWEEP_ARGS --jobs 2 -o "$tmp/one" 2>"$tmp/one.err"
t3=$(date +%s.%N)
check "one process writes the whole grid" '[ -s "$tmp/one/cases.csv" ]'
check "the merged data set equals it, byte for byte (diff -r)" \
    'diff -r "$tmp/one" "$tmp/merged" >"$tmp/diff" 2>&1 || { sed "s/^/# /" "$tmp/diff" | head -n 20; false; }'

# The times: from submission to the merged data set, and each job's from its completion
# record (Slurm's clock has whole seconds).
awk -v t0="$t0" -v t1="$t1" -v t2="$t2" -v t3="$t3" 'BEGIN {
    printf "# wall time, submission to merged data set: %.1f s\n", t1 - t0
    printf "# wall time, one process (--jobs 2): %.1f s\n", t3 - t2 }'
awk -v merge="$merge" '
    function secs(s,   d, t) { split(s, d, /[-T:]/); return mktime(d[1] " " d[2] " " d[3] " " d[4] " " d[5] " " d[6]) }
    {
        for (i = 1; i <= NF; ++i) { split($i, kv, "="); f[kv[1]] = kv[2] }
        what = f["ArrayTaskId"] != "" ? "shard " f["ArrayTaskId"] : (f["JobId"] == merge ? "merge" : "job " f["JobId"])
        printf "# %-8s %s to %s: %d s\n", what, f["StartTime"], f["EndTime"], secs(f["EndTime"]) - secs(f["StartTime"])
        delete f
    }' "$cluster/jobcomp.log" | sort
echo "$((n - failed)) passed, $failed failed"
[ "$failed" -eq 0 ]
