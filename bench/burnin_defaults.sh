#!/bin/sh
# Measures what the burn-in defaults were chosen from: error (MSE against a
# long PT reference) of MLT with OMC burn-in on cornell-water for several
# large-step probabilities and burn-in round counts, at equal wall time.
# Usage: bench/burnin_defaults.sh [BIN]
set -eu
BIN=${1:-build/smallmlt}
SCENE=${SCENE:-cornell-water}
SIZE=${SIZE:-128}
T=${T:-16}
OUT=bench/results/burnin
mkdir -p "$OUT"
ref=$(sh bench/reference.sh "$BIN" "$SCENE" "$SIZE")
common="scenes/$SCENE.scene --width $SIZE --height $SIZE --seed 7 --quiet --time $T"
echo "large_step,burn_in_iters,mse,rel_mse"
for p in 0.05 0.1 0.2 0.3 0.5; do
    "$BIN" render $common --large-step "$p" --out "$OUT/p.pfm"
    "$BIN" compare "$OUT/p.pfm" "$ref" | awk -v p="$p" '{print p ",32," $2 "," $4}'
done
for it in 1 2 4 8 16 32 64; do
    "$BIN" render $common --burn-in-iters "$it" --out "$OUT/p.pfm"
    "$BIN" compare "$OUT/p.pfm" "$ref" | awk -v it="$it" '{print "0.1," it "," $2 "," $4}'
done
