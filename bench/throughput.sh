#!/bin/sh
# Path-tracing throughput: paths per second and rays per second (closest-hit
# plus shadow rays) for cornell and cornell-water at 256x256 on the default
# device. One warm-up render per scene, then RUNS renders; prints the median.
# Usage: bench/throughput.sh [BIN] [RUNS]
set -eu
BIN=${1:-build/smallmlt}
RUNS=${2:-5}
SPP=${SPP:-32}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

echo "device: $("$BIN" devices | sed -n '1p')"
echo "cores: $(nproc)   renders per scene: $RUNS (after one warm-up), 256x256, $SPP spp"
printf '%-16s %14s %14s %16s\n' scene "M paths/s" "M rays/s" "M rays/s/core"
for scene in cornell cornell-water; do
    "$BIN" render "scenes/$scene.scene" --method pt --width 256 --height 256 --spp "$SPP" --out "$TMP/w.png" >/dev/null
    : > "$TMP/log"
    i=0
    while [ "$i" -lt "$RUNS" ]; do
        "$BIN" render "scenes/$scene.scene" --method pt --width 256 --height 256 --spp "$SPP" --out "$TMP/r.png" >> "$TMP/log"
        i=$((i + 1))
    done
    paths=$(sed -n 's/.*, \([0-9.]*\) M paths\/s.*/\1/p' "$TMP/log" | median)
    rays=$(sed -n 's/.*, \([0-9.]*\) M rays\/s.*/\1/p' "$TMP/log" | median)
    per_core=$(echo "$rays $(nproc)" | awk '{printf "%.2f", $1 / $2}')
    printf '%-16s %14s %14s %16s\n' "$scene" "$paths" "$rays" "$per_core"
done
