#!/bin/sh
# MLT on several ranks against one process, on this machine: 1 rank with 2
# PoCL threads, 2 ranks with 1 thread each, and 1 rank with 1 thread (the
# per-core baseline), each rank sizing itself to its device (--threads
# auto). Per configuration and run: the wall time of a --spp render and the
# mutations/s of its steps summed over ranks; and the error against a long
# PT reference after each of TIMES seconds (time to error). Medians of RUNS
# go to $RESULTS/ranks/summary.csv.
# Usage: bench/ranks.sh [BIN]  (smallmlt-mpi beside BIN; environment: SCENE,
# SIZE, SPP, TIMES, RUNS, REF_SECONDS, THREADS: per rank, default auto)
set -eu
BIN=${1:-build/smallmlt}
MPI_BIN=$(dirname "$BIN")/smallmlt-mpi
SCENE=${SCENE:-cornell-water}
SIZE=${SIZE:-128}
SPP=${SPP:-64}
TIMES=${TIMES:-10 20}
RUNS=${RUNS:-3}
THREADS=${THREADS:-auto}
OUT=${RESULTS:-bench/results}/ranks
mkdir -p "$OUT"
REF=$(sh bench/reference.sh "$BIN" "$SCENE" "$SIZE")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "config,run,what,value" > "$OUT/runs.csv"
# job NP THREADS_PER_RANK ARGS...: one render, its output on stdout
job() {
    np=$1 pt=$2
    shift 2
    mpirun --oversubscribe --bind-to none -x POCL_MAX_PTHREAD_COUNT="$pt" -np "$np" \
        "$MPI_BIN" render "scenes/$SCENE.scene" --width "$SIZE" --height "$SIZE" \
        --threads "$THREADS" "$@" 2>&1
}
for run in $(seq 1 "$RUNS"); do
    for config in 1x2 2x1 1x1; do
        np=${config%x*} pt=${config#*x}
        t0=$(date +%s.%N)
        out=$(job "$np" "$pt" --spp "$SPP" --seed "$run" --out "$OUT/last.pfm")
        t1=$(date +%s.%N)
        echo "$config,$run,wall_s,$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" >> "$OUT/runs.csv"
        m=$(printf '%s\n' "$out" | sed -n 's/.* \([0-9.e+-]*\) M mutations\/s.*/\1/p' |
            awk '{s += $1} END {print s * 1e6}')
        echo "$config,$run,mutations_per_s,$m" >> "$OUT/runs.csv"
        for t in $TIMES; do
            e=$(job "$np" "$pt" --time "$t" --seed "$run" --reference "$REF" --out "$OUT/last.pfm" |
                sed -n 's/^error against .*: mse \([0-9.e+-]*\) .*/\1/p')
            echo "$config,$run,mse_at_${t}s,$e" >> "$OUT/runs.csv"
        done
    done
done
rm -f "$OUT/last.pfm"
awk -F, -f bench/median.awk -f bench/ranks_summary.awk "$OUT/runs.csv" | tee "$OUT/summary.csv"
