#!/bin/sh
# The paper's Figure 1 on cornell-water: the paper's MLT without burn-in (no split, large step 0.5),
# MLT with OMC burn-in (the defaults) and PT, each rendered for the same wall
# times; images at three of them side by side, and error (MSE against a long
# PT reference, linear HDR) against time for all three in one log-log chart.
# Writes bench/results/burnin/. Usage: bench/burnin.sh [BIN]
# THREADS sets MLT's thread count (default auto). PLOT_ONLY=1 redraws the pictures from the last run's files.
set -eu
BIN=${1:-build/smallmlt}
SCENE=${SCENE:-cornell-water}
SIZE=${SIZE:-128}
TIMES=${TIMES:-1 2 4 8 16 32}
SHOW=${SHOW:-8 16 32} # time points in the picture
OUT=${RESULTS:-bench/results}/burnin
mkdir -p "$OUT"
ref=$(sh bench/reference.sh "$BIN" "$SCENE" "$SIZE")
csv="$OUT/error.csv"
common="scenes/$SCENE.scene --width $SIZE --height $SIZE --seed 7 --quiet"
mlt="--method mlt ${THREADS:+--threads $THREADS}"
[ -n "${PLOT_ONLY:-}" ] || echo "method,seconds,mse,rel_mse" > "$csv"
[ -n "${PLOT_ONLY:-}" ] && TIMES=""
for t in $TIMES; do
    "$BIN" render $common $mlt --split none --burn-in none --large-step 0.5 --time "$t" \
        --out "$OUT/none-$t.pfm" --out "$OUT/none-$t.png"
    "$BIN" render $common $mlt --time "$t" --out "$OUT/omc-$t.pfm" --out "$OUT/omc-$t.png"
    "$BIN" render $common --method pt --time "$t" --out "$OUT/pt-$t.pfm" --out "$OUT/pt-$t.png"
    for m in none omc pt; do
        "$BIN" compare "$OUT/$m-$t.pfm" "$ref" |
            awk -v m="$m" -v t="$t" '{print m "," t "," $2 "," $4}' >> "$csv"
    done
done
cat "$csv"

set -- $SHOW
{
    echo "set terminal pngcairo size 900,640 font ',10'"
    echo "set output '$OUT/figure1.png'"
    echo "set multiplot layout 2,3"
    echo "unset border; unset tics; unset key; set size ratio -1"
    for row in none omc; do
        label="without burn-in, large step 0.5"
        [ "$row" = omc ] && label="OMC burn-in (defaults)"
        for t in "$@"; do
            echo "set title '$label, $t s'"
            echo "plot '$OUT/$row-$t.png' binary filetype=png with rgbimage"
        done
    done
    echo "unset multiplot"
} | gnuplot
sh bench/plot_error.sh "$csv" "$OUT/error.png" "$SCENE ${SIZE}x$SIZE" \
    "none=MLT, no burn-in, large step 0.5" "omc=MLT, OMC burn-in" "pt=PT"
echo "wrote $OUT/figure1.png and $OUT/error.png"
