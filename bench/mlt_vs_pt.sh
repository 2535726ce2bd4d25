#!/bin/sh
# MLT mutations per second against PT paths per second on the same scene,
# film and thread count, runs alternating PT and MLT; prints the medians and
# their ratio (the cost of lazy proposals and packed states), and the bytes
# of one chain's state. Usage: bench/mlt_vs_pt.sh [BIN] [RUNS] [SCENE...]
set -eu
BIN=${1:-build/smallmlt}
RUNS=${2:-5}
shift 2 2>/dev/null || shift $#
SCENES=${*:-cornell cornell-water}
SPP=${SPP:-32}
LARGE_STEP=${LARGE_STEP:-0.5} # the paper's baseline; the default with burn-in (0.1) commits more small steps
SIZE=${SIZE:-256}
THREADS=$((SIZE * SIZE)) # PT runs one work-item per pixel; MLT as many chains
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

echo "device: $("$BIN" devices | sed -n '1p'), cores: $(nproc)"
echo "${SIZE}x${SIZE}, $SPP paths (PT) or mutations (MLT) per pixel, $THREADS threads, large step $LARGE_STEP, $RUNS runs each, alternating"
printf '%-16s %12s %16s %8s %14s\n' scene "PT M paths/s" "MLT M mutations/s" ratio "state B/chain"
for scene in $SCENES; do
    common="scenes/$scene.scene --width $SIZE --height $SIZE --spp $SPP"
    "$BIN" render $common --method pt --out "$TMP/w.png" >/dev/null
    "$BIN" render $common --method mlt --split none --large-step "$LARGE_STEP" --threads "$THREADS" --out "$TMP/w.png" >/dev/null
    : > "$TMP/pt"
    : > "$TMP/mlt"
    i=0
    while [ "$i" -lt "$RUNS" ]; do
        "$BIN" render $common --method pt --out "$TMP/r.png" >> "$TMP/pt"
        "$BIN" render $common --method mlt --split none --large-step "$LARGE_STEP" --threads "$THREADS" --out "$TMP/r.png" >> "$TMP/mlt"
        i=$((i + 1))
    done
    pt=$(sed -n 's/.*, \([0-9.]*\) M paths\/s.*/\1/p' "$TMP/pt" | median)
    mlt=$(sed -n 's/.*, \([0-9.e+-]*\) M mutations\/s.*/\1/p' "$TMP/mlt" | median)
    bytes=$(sed -n 's/.*state \([0-9]*\) B\/chain.*/\1/p' "$TMP/mlt" | head -n 1)
    printf '%-16s %12s %16s %8s %14s\n' "$scene" "$pt" "$mlt" "$(echo "$mlt $pt" | awk '{printf "%.2f", $1 / $2}')" "${bytes:-?}"
done
