#!/bin/sh
# Runs a tirenv sweep on a Slurm cluster: one array task per shard (sweep.sbatch), then one
# job that merges the shards (merge.sbatch), submitted to start only when every shard has
# succeeded (--dependency=afterok). The merged data set is byte for byte what a single
# 'tirenv sweep' of the whole grid writes; see 'tirenv sweep --help' and README.md.
#
#   sh scripts/slurm/submit.sh                     # the knobs below
#   SHARDS=16 CPUS=8 OUT=/scratch/me/grid sh scripts/slurm/submit.sh
#
# Run it from a directory every node sees (the logs go beside OUT). A shard that fails or is
# cancelled can be submitted again alone (sbatch --array=K ... sweep.sbatch, with the same
# environment): it keeps the cases already written. Then submit merge.sbatch.
# SPDX-License-Identifier: Apache-2.0
set -eu

# --- knobs (each may be set in the environment instead) -------------------------------------
# The tirenv program, as the nodes see it.
TIRENV=${TIRENV:-tirenv}
# The merged data set; shard K is written to $OUT.parts/K, the jobs' logs to $OUT.parts/.
OUT=${OUT:-$PWD/sweep}
# Array tasks (shards): case i goes to shard i mod SHARDS.
SHARDS=${SHARDS:-4}
# Cores per task: the shard runs that many cases at once (tirenv sweep --jobs).
CPUS=${CPUS:-1}
# Time limit per task (HH:MM:SS), and the partition (empty: the cluster's default).
TIME=${TIME:-02:00:00}
PARTITION=${PARTITION:-}
# The grid: 5 lengths x 5 heights x 4 contact lengths x 2 inflation pressures = 200 cases of
# the ring reference tire on the virtual rig (a swept key must be one the model reads: the
# ring's air, not the springs model's RADIAL_STIFFNESS).
SWEEP_ARGS=${SWEEP_ARGS:---lengths 0.05,0.1,0.15,0.2,0.3 --heights 0.025,0.05,0.075,0.1,0.125
--contact-lengths 0.28,0.33,0.38,0.43 --set INFLPRES=0.8e5,1.6e5 --model ring --rig}
# ---------------------------------------------------------------------------------------------

here=$(cd "$(dirname "$0")" && pwd)
case $OUT in /*) ;; *) OUT=$PWD/$OUT ;; esac
mkdir -p "$OUT.parts"  # Slurm does not create the directories of its log files
export TIRENV OUT SHARDS SWEEP_ARGS

# The shards: an array of SHARDS tasks.
array=$(sbatch --parsable --job-name=tirenv-sweep --array="0-$((SHARDS - 1))" \
    --ntasks=1 --cpus-per-task="$CPUS" --time="$TIME" ${PARTITION:+--partition="$PARTITION"} \
    --output="$OUT.parts/shard-%a.log" "$here/sweep.sbatch")
array=${array%%;*}  # "JOBID;CLUSTER" on a federation

# The merge, once every task of the array has ended well.
merge=$(sbatch --parsable --job-name=tirenv-merge --dependency="afterok:$array" \
    --ntasks=1 --cpus-per-task=1 --time="$TIME" ${PARTITION:+--partition="$PARTITION"} \
    --output="$OUT.parts/merge.log" "$here/merge.sbatch")
merge=${merge%%;*}

echo "submitted: shards job $array ($SHARDS array tasks), merge job $merge (after all succeed)"
echo "follow:    squeue -j $array,$merge; logs in $OUT.parts/"
echo "result:    $OUT"
