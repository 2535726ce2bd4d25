#!/bin/sh
# Device memory against path depth, from `smallmlt budget` (no rendering):
# MLT chain states packed to the scene's layout for K = 1, 2, 4 proposals
# per chain, against float32 states holding x and a stored proposal y (the
# naive layout), at the paper's thread count; and the whole render's total
# for K = 1. Writes bench/results/memory/. Usage: bench/memory.sh [BIN]
set -eu
BIN=${1:-build/smallmlt}
SCENE=${SCENE:-cornell-water}
THREADS=${THREADS:-262144}
DEPTH=${DEPTH:-24}
OUT=${RESULTS:-bench/results}/memory
mkdir -p "$OUT"
for k in 1 2 4; do
    "$BIN" budget "scenes/$SCENE.scene" --threads "$THREADS" --proposals "$k" --depth "$DEPTH" \
        --format csv > "$OUT/k$k.csv"
done
MiB=1048576
{
    echo "set terminal pngcairo size 640,420 font ',10'"
    echo "set output '$OUT/memory.png'"
    echo "set datafile separator ','"
    echo "set grid; set key top left"
    echo "set xlabel 'maximum depth (bounces)'; set ylabel 'MiB'"
    echo "set title 'device memory, $SCENE, $THREADS threads'"
    echo "plot '$OUT/k1.csv' every ::1 using 1:(\$9/$MiB) with linespoints title 'naive float32 x + y states', \\"
    echo "     '$OUT/k1.csv' every ::1 using 1:(\$8/$MiB) with linespoints title 'whole render, K = 1', \\"
    for k in 1 2 4; do
        sep=", \\"
        [ "$k" = 4 ] && sep=""
        echo "     '$OUT/k$k.csv' every ::1 using 1:(\$6/$MiB) with linespoints title 'packed states, K = $k'$sep"
    done
} | gnuplot
awk -F, -v d="$DEPTH" 'NR > 1 && $1 == d {printf "depth %d: packed states %.1f MiB, whole render %.1f MiB, naive float32 states %.1f MiB (K = 1)\n", d, $6 / 1048576, $8 / 1048576, $9 / 1048576}' "$OUT/k1.csv"
echo "wrote $OUT/memory.png"
