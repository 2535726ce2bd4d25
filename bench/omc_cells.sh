#!/bin/sh
# The OMC part's cells (--omc-cells, src/render/omc_cells.hpp) against the
# same render without them and against path tracing, at equal time: one
# render per (scene, method, seed), and each method's MSE and 8x8 / 32x32
# block MSE from the spread of its renders over the seeds
# (bench/seed_mse.py), with their ratios to PT's.
# Writes bench/results/omc_cells/. Usage: bench/omc_cells.sh [BIN]
# Settings (environment): SCENES, SIZE (an N x N film), SECONDS, SEEDS,
# METHODS (pt, off: --omc-cells off, on: --omc-cells on, onE: that and
# --omc-effort E).
set -eu
BIN=${1:-build/smallmlt}
SCENES=${SCENES:-ajar cornell-glass cornell-water}
SIZE=${SIZE:-128}
SECONDS_=${SECONDS:-10}
SEEDS=${SEEDS:-1 2 3 4 5 6}
METHODS=${METHODS:-pt off on}
OUT=${RESULTS:-bench/results}/omc_cells
mkdir -p "$OUT"

flags() {
    case $1 in
    pt) echo "--method pt" ;;
    off) echo "--method mlt --omc-cells off" ;;
    on) echo "--method mlt --omc-cells on" ;;
    on*) echo "--method mlt --omc-cells on --omc-effort ${1#on}" ;;
    *) echo "omc_cells.sh: unknown method $1" >&2; exit 2 ;;
    esac
}

echo "device: $("$BIN" devices | sed -n '1p'), cores: $(nproc)" | tee "$OUT/machine.txt"
: > "$OUT/summary.txt"
for scene in $SCENES; do
    for m in $METHODS; do # an earlier run's renders of other seeds or films
        rm -f "$OUT/$scene-$m-"*.pfm "$OUT/$scene-$m-"*.log
    done
    for seed in $SEEDS; do
        for m in $METHODS; do
            # shellcheck disable=SC2046
            "$BIN" render "scenes/$scene.scene" --width "$SIZE" --height "$SIZE" \
                --time "$SECONDS_" --seed "$seed" $(flags "$m") \
                --out "$OUT/$scene-$m-$seed.pfm" > "$OUT/$scene-$m-$seed.log" 2>&1
        done
    done
    # shellcheck disable=SC2086
    python3 bench/seed_mse.py "$OUT" "$scene" $METHODS | tee -a "$OUT/summary.txt"
done
