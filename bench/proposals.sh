#!/bin/sh
# Split-transition MLT, the paper's Figures 3 and 4 on cornell-water: crops
# at equal time for K = 1, 2, 4 proposals per chain side by side, and error
# (MSE against a long PT reference, linear HDR) against time for K = 1, 2,
# 4, 8, 16 in one chart. Same threads for every K (so N/K chains).
# THREADS sets the thread count (default auto).
# Writes bench/results/proposals/. Usage: bench/proposals.sh [BIN]
set -eu
BIN=${1:-build/smallmlt}
SCENE=${SCENE:-cornell-water}
SIZE=${SIZE:-128}
TIMES=${TIMES:-8 16 32}
KS=${KS:-1 2 4 8 16}
OUT=${RESULTS:-bench/results}/proposals
mkdir -p "$OUT"
ref=$(sh bench/reference.sh "$BIN" "$SCENE" "$SIZE")
csv="$OUT/error.csv"
echo "proposals,seconds,mse,rel_mse" > "$csv"
common="scenes/$SCENE.scene --width $SIZE --height $SIZE --seed 7 --quiet"
for t in $TIMES; do
    for k in $KS; do
        "$BIN" render $common ${THREADS:+--threads $THREADS} --proposals "$k" --time "$t" --out "$OUT/k$k-$t.pfm" --out "$OUT/k$k-$t.png"
        "$BIN" compare "$OUT/k$k-$t.pfm" "$ref" |
            awk -v k="$k" -v t="$t" '{print k "," t "," $2 "," $4}' >> "$csv"
    done
done
cat "$csv"
last=$(echo "$TIMES" | awk '{print $NF}')
{
    echo "set terminal pngcairo size 900,340 font ',10'"
    echo "set output '$OUT/crops.png'"
    echo "set multiplot layout 1,3"
    echo "unset border; unset tics; unset key; set size ratio -1"
    # the lower middle of the film: the caustics on the floor under water
    echo "set xrange [$((SIZE / 4)):$((3 * SIZE / 4))]; set yrange [0:$((SIZE / 2))]"
    for k in 1 2 4; do
        echo "set title 'K = $k, $last s'"
        echo "plot '$OUT/k$k-$last.png' binary filetype=png with rgbimage"
    done
    echo "unset multiplot"
} | gnuplot
set --
for k in $KS; do set -- "$@" "$k=K = $k"; done
sh bench/plot_error.sh "$csv" "$OUT/error.png" "split-transition MLT, $SCENE ${SIZE}x$SIZE" "$@"
echo "wrote $OUT/crops.png and $OUT/error.png"
