#!/bin/sh
# Throughput against thread count, the analogue of the paper's Figure 2: MLT
# mutations per second (steps only) on cornell-water for N = 2^8 up to the
# automatic count (or MAX_THREADS), same work (mutations per pixel) at every N; median of RUNS.
# Writes bench/results/threads/threads.csv and threads.png.
# Usage: bench/threads.sh [BIN] [RUNS]
set -eu
BIN=${1:-build/smallmlt}
RUNS=${2:-3}
SCENE=${SCENE:-cornell-water}
SIZE=${SIZE:-128}
SPP=${SPP:-64}
OUT=${RESULTS:-bench/results}/threads
mkdir -p "$OUT"
median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
auto=$("$BIN" render "scenes/$SCENE.scene" --width 8 --height 8 --spp 1 --out "$OUT/probe.png" |
    sed -n 's/^threads: \([0-9]*\) (auto.*/\1/p')
echo "threads,mutations_per_s" > "$OUT/threads.csv"
n=256
max=${MAX_THREADS:-$auto}
[ "$max" -le "$auto" ] || max=$auto
while [ "$n" -le "$max" ]; do
    : > "$OUT/log"
    i=0
    while [ "$i" -lt "$RUNS" ]; do
        "$BIN" render "scenes/$SCENE.scene" --width "$SIZE" --height "$SIZE" --spp "$SPP" \
            --threads "$n" --out "$OUT/r.png" >> "$OUT/log"
        i=$((i + 1))
    done
    rate=$(sed -n 's/.*, \([0-9.e+-]*\) M mutations\/s.*/\1/p' "$OUT/log" | median)
    echo "$n,$rate" | tee -a "$OUT/threads.csv"
    n=$((n * 2))
done
{
    echo "set terminal pngcairo size 640,420 font ',10'"
    echo "set output '$OUT/threads.png'"
    echo "set datafile separator ','"
    echo "set logscale x 2; set grid; set key off"
    echo "set xlabel 'threads (chains)'; set ylabel 'M mutations/s'"
    echo "set title 'MLT throughput against thread count, $SCENE ${SIZE}x$SIZE'"
    echo "plot '$OUT/threads.csv' every ::1 using 1:2 with linespoints"
} | gnuplot
echo "wrote $OUT/threads.png"
