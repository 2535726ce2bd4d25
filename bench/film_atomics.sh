#!/bin/sh
# MLT throughput of the 32-bit film (the default: 32-bit atomics, drained to
# the host every S steps) against the 64-bit reference film (64-bit atomics,
# never drained), side by side in one binary (bench/ab_mutations.sh,
# alternating runs), at each film size of SIZES: a larger film costs the
# 32-bit film more per drain. Writes $RESULTS/film_atomics/summary.csv:
# size, scene, medians of mutations/s of each, their ratio 32/64.
# Usage: bench/film_atomics.sh [BIN]  (environment: SIZES, SCENES, SPP, THREADS, RUNS)
set -eu
BIN=${1:-build/smallmlt}
SIZES=${SIZES:-128 512}
RESULTS=${RESULTS:-bench/results}
OUT=$RESULTS/film_atomics
mkdir -p "$OUT"
echo "size,scene,mutations_per_s_64,mutations_per_s_32,ratio_32_over_64,atomics_per_mutation_64,atomics_per_mutation_32" > "$OUT/summary.csv"
# The 64-bit film needs 64-bit atomics (device 0's third line of `devices`).
rm -f "$OUT/skipped"
if ! "$BIN" devices | sed -n 3p | grep -q "64-bit atomics"; then
    echo "skipped: device 0 lacks cl_khr_int64_base_atomics, which the 64-bit film needs" |
        tee "$OUT/skipped"
    exit 0
fi
for size in $SIZES; do
    RESULTS=$OUT/size$size SIZE=$size FLAGS_A="--split none --film-atomics 64" \
        FLAGS_B="--split none --film-atomics 32" \
        sh bench/ab_mutations.sh "$BIN" "$BIN" > /dev/null
    tail -n +2 "$OUT/size$size/ab_mutations/summary.csv" | sed "s/^/$size,/" >> "$OUT/summary.csv"
done
cat "$OUT/summary.csv"
