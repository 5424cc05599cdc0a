#!/bin/sh
# tirenv study killed at random moments, four times in a row (TIRENV_KILLS=N for more), over
# an existing report: after each kill the directory holds the old report or the new one, whole, never a mixture (a file
# list and a checksum of every file compared with the two reference states). Runs alternate
# between --seed 1 and --seed 2, whose networks differ, so old and new are told apart. Some
# files hold measured times and differ between two runs of one seed (report.md, errors.md,
# timing.csv, nn*.json): an old state must match them byte for byte, a new one must have
# replaced every one of them. SIGTERM and SIGINT must leave no staging directory; SIGKILL
# may, and the next run removes it. The kill times are drawn up to 1.3 times a reference
# run's time, so that some runs complete. On the test data set of three cases (every stage of
# the study, every kind of file, 40 % less time than the embedded data set's 28), without
# images (gnuplot's time, not tirenv's: the images are written and renamed inside the staging
# directory like every other file). The first reference runs at --jobs 3 (more threads than
# this machine's cores) and the complete run at the end at --jobs 1: they write the same files
# apart from the timings they report, the study's --jobs check (its fit, networks over the
# seeds, physical network's grid, obstacles outside, the three parts side by side), made
# here on the runs the test needs anyway. Usage: tests/study/study_killed.sh BIN TESTDATA_DIR.
# TIRENV_KILL_SEED repeats a run's kill times. Each run draws new times, so that the runs of
# the test over time cover the study's stages; ten kills a run cost twice the time of four.
# SPDX-License-Identifier: Apache-2.0
# $run is split on purpose (SC2086).
# shellcheck disable=SC2086
set -u
bin=$1
data=$2/dataset_good
case $bin in /*) ;; */*) bin=$PWD/$bin ;; esac
case $data in /*) ;; *) data=$PWD/$data ;; esac
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 2
pass=0 fail=0
ok() { pass=$((pass + 1)); echo "ok $pass - $1"; }
not_ok() { fail=$((fail + 1)); echo "not ok $((pass + fail)) - $1"; }

# snap DIR [volatile|stable]: "checksum path" per file, sorted; only the files whose bytes
# vary between runs of one seed, or only the others; default all.
snap() {
    (cd "$1" && find . -type f | sort | while read -r f; do
        case $(basename "$f") in
        report.md | errors.md | timing.csv | nn.json | nn-physical.json) kind=volatile ;;
        *) kind=stable ;;
        esac
        [ "${2:-all}" = all ] || [ "$2" = $kind ] || continue
        echo "$(cksum <"$f" | cut -d' ' -f1) $f"
    done)
}
files() { (cd "$1" && find . -type f | sort); }

study() { # study SEED DIR [OPTION...]
    seed=$1 dir=$2
    shift 2
    "$bin" study --data "$data" --no-images --seed "$seed" -o "$dir" "$@" >/dev/null 2>&1
}

t0=$(date +%s.%N)
study 1 ref1 --jobs 3 || { echo "not ok 1 - the reference study (seed 1) failed"; exit 1; }
t1=$(date +%s.%N)
study 2 ref2 || { echo "not ok 1 - the reference study (seed 2) failed"; exit 1; }
T=$(echo "$t0 $t1" | awk '{ print $2 - $1 }')
snap ref1 stable >ref1.stable
snap ref2 stable >ref2.stable
files ref1 >ref1.files
files ref2 >ref2.files
if cmp -s ref1.stable ref2.stable; then
    echo "not ok 1 - seeds 1 and 2 give the same report: old and new cannot be told apart"
    exit 1
fi

seed=${TIRENV_KILL_SEED:-$(date +%s)}
echo "# one study takes ${T} s; kill times from seed $seed (TIRENV_KILL_SEED=$seed repeats them)"
# $kills kill times (default 4), each drawn anew; the signals cycle through TERM, INT and KILL
# from a random start, so that four kills meet each of them at least once.
kills=${TIRENV_KILLS:-4}
awk -v s="$seed" -v T="$T" -v n="$kills" 'BEGIN { srand(s); off = int(rand() * 3)
    for (i = 0; i < n; i++)
        printf "%.2f %s\n", 0.2 + rand() * 1.3 * T, substr("TIK", (i + off) % 3 + 1, 1) }' \
    >plan

cp -R ref1 rep
state=1
n_old=0 n_new=0
i=0
while read -r delay how; do
    i=$((i + 1))
    next=$((3 - state))
    snap rep >before
    # The study's arguments as the positional parameters: the data set's path stays one word.
    set -- study --data "$data" --no-images --seed "$next" -o rep
    case $how in
    I) env --default-signal=INT "$bin" "$@" >/dev/null 2>&1 & sig=INT ;;
    K) "$bin" "$@" >/dev/null 2>&1 & sig=KILL ;;
    *) "$bin" "$@" >/dev/null 2>&1 & sig=TERM ;;
    esac
    pid=$!
    sleep "$delay"
    kill -s $sig $pid 2>/dev/null
    wait $pid 2>/dev/null
    rc=$?
    snap rep >after
    if cmp -s before after; then
        verdict=old
        n_old=$((n_old + 1))
    elif files rep | cmp -s - ref$next.files && snap rep stable | cmp -s - ref$next.stable &&
        ! snap rep volatile | grep -q -F -x -f - before; then
        verdict=new
        n_new=$((n_new + 1))
        state=$next
    else
        verdict=mixture
    fi
    staging=$(find . -maxdepth 1 -name '.rep.tirenv-tmp.*' | wc -l)
    what="kill $i: SIG$sig after $delay s (exit $rc): the $verdict report"
    if [ $rc -eq 1 ]; then
        # Misuse: the study never ran, so the old report proves nothing.
        not_ok "$what: the command was refused"
    elif [ $verdict = mixture ]; then
        not_ok "$what"
        diff before after | head -20 | sed 's/^/#   /'
    elif [ $sig != KILL ] && [ "$staging" -ne 0 ]; then
        not_ok "$what, but a staging directory is left after SIG$sig"
    elif [ "$staging" -ne 0 ]; then
        ok "$what, its staging directory left (SIGKILL)"
    else
        ok "$what"
    fi
done <plan
echo "# $n_old kills left the old report, $n_new the new one"

study 1 rep --jobs 1
if [ -z "$(find . -name '*tirenv-tmp*')" ] && snap rep stable | cmp -s - ref1.stable; then
    ok "a complete run afterwards writes the report and removes every staging directory left"
else
    not_ok "a complete run afterwards writes the report and removes every staging directory left"
fi
# shellcheck source=tests/lib/untimed.sh
. "$here/../lib/untimed.sh"
if same_apart_from_timings ref1 rep; then
    ok "--jobs 1 = --jobs 3: the fit, networks, errors, plot data, reports"
else
    not_ok "--jobs 1 = --jobs 3: the fit, networks, errors, plot data, reports"
fi
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
