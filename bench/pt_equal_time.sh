#!/bin/sh
# Path tracing at equal time under several settings: one render per (scene,
# setting, seed), MSE and relative MSE against a long reference
# (bench/reference.sh). Prints per scene and setting the medians over seeds
# and the ratio of the median MSE to the first setting's; the last lines give
# the geometric mean of those ratios over the scenes. Settings are
# "name=flags" words (flags joined by '+'); the default compares the path
# tracer of earlier versions with today's defaults.
# Writes bench/results/pt_equal_time/NAME.csv and NAME-summary.csv.
# Usage: bench/pt_equal_time.sh [BIN]
# Settings (environment): NAME, SCENES, SIZE, SECONDS, SEEDS, CONFIGS.
set -eu
BIN=${1:-build/smallmlt}
NAME=${NAME:-defaults}
SCENES=${SCENES:-cornell cornell-water cornell-glass ajar}
SIZE=${SIZE:-128}
SECONDS_=${SECONDS:-30}
SEEDS=${SEEDS:-1 2 3}
CONFIGS=${CONFIGS:-old=--sampler+random+--rr-threshold+1+--rr-cap+0.95 new=}
OUT=${RESULTS:-bench/results}/pt_equal_time
mkdir -p "$OUT"
csv="$OUT/$NAME.csv"
echo "device: $("$BIN" devices | sed -n '1p'), cores: $(nproc)" > "$OUT/machine.txt"
echo "scene,setting,seed,seconds,spp,mse,rel_mse" > "$csv"
for scene in $SCENES; do
    ref=$(sh bench/reference.sh "$BIN" "$scene" "$SIZE")
    for seed in $SEEDS; do
        for c in $CONFIGS; do
            name=${c%%=*}
            flags=$(echo "${c#*=}" | tr + ' ')
            # shellcheck disable=SC2086
            "$BIN" render "scenes/$scene.scene" --method pt $flags --width "$SIZE" \
                --height "$SIZE" --time "$SECONDS_" --seed "$seed" --reference "$ref" \
                --out "$OUT/last.pfm" > "$OUT/last.txt"
            awk -v s="$scene" -v n="$name" -v seed="$seed" '
                / pt: / { t = $0; sub(/.*pt: /, "", t); split(t, a, " "); secs = a[1]
                          spp = $0; sub(/ spp.*/, "", spp); sub(/.*, /, "", spp) }
                /^error against/ { mse = $5; rel = $7 }
                END { print s "," n "," seed "," secs "," spp "," mse "," rel }' \
                "$OUT/last.txt" >> "$csv"
        done
    done
done
rm -f "$OUT/last.pfm" "$OUT/last.txt"
awk -F, -f bench/median.awk -f bench/pt_summary.awk "$csv" | tee "$OUT/$NAME-summary.csv"
