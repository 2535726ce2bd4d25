#!/bin/sh
# MLT throughput of two binaries side by side: renders each scene with A and
# B in turn (A B A B ...), RUNS times each, and prints the median mutations/s
# of the steps (the render summary's figure, which leaves out burn-in and
# set-up) of each, their ratio B/A, and each binary's global atomics per
# mutation where its summary gives them. Usage: bench/ab_mutations.sh BIN_A BIN_B
# Settings (environment): SCENES, SIZE, SPP, THREADS, RUNS; FLAGS_A and
# FLAGS_B are added to A's and B's command lines, so that one binary can be
# run both ways (FLAGS_A="--film-atomics 64": the 64-bit film against the
# 32-bit one).
set -eu
A=$1 B=$2
SCENES=${SCENES:-cornell cornell-water}
SIZE=${SIZE:-128}
SPP=${SPP:-64}
THREADS=${THREADS:-65536}
RUNS=${RUNS:-5}
FLAGS_A=${FLAGS_A:-}
FLAGS_B=${FLAGS_B:-}
OUT=${RESULTS:-bench/results}/ab_mutations
mkdir -p "$OUT"
echo "scene,binary,run,mutations_per_s,atomics_per_mutation" > "$OUT/runs.csv"
for scene in $SCENES; do
    r=1
    while [ "$r" -le "$RUNS" ]; do
        for bin in A B; do
            if [ "$bin" = A ]; then exe=$A flags=$FLAGS_A; else exe=$B flags=$FLAGS_B; fi
            # shellcheck disable=SC2086 # the flags are words
            "$exe" render "scenes/$scene.scene" --method mlt --threads "$THREADS" --spp "$SPP" $flags \
                --width "$SIZE" --height "$SIZE" --seed "$r" --out "$OUT/last.pfm" |
                awk -v s="$scene" -v b="$bin" -v r="$r" '/ mlt: / {
                    m = $0; sub(/ M mutations\/s.*/, "", m); sub(/.*, /, "", m)
                    a = "NA"; if ($0 ~ /global atomics/) { a = $0; sub(/ global atomics.*/, "", a); sub(/.*, /, "", a) }
                    print s "," b "," r "," m * 1e6 "," a }' >> "$OUT/runs.csv"
        done
        r=$((r + 1))
    done
done
rm -f "$OUT/last.pfm"
awk -F, -f bench/median.awk -f bench/ab_summary.awk \
    "$OUT/runs.csv" | tee "$OUT/summary.csv"
