#!/bin/sh
# Stuck chains on tiny-caustic (a 1 cm light focused by a glass ball into a
# small, very bright caustic): error against time (MSE against a long PT
# reference) for PT and for MLT at several large-step probabilities, with
# the stuck-chain counts each MLT render reports (chains that rejected
# STUCK_RUN proposals in a row, and the longest run). Few threads, as on a
# small device, so that every chain runs many steps. The chains run
# whatever the burn-in found (--split visible: --split auto path traces the
# scene when the burn-in misses the caustic's paths).
# Writes bench/results/stuck/. Usage: bench/stuck.sh [BIN]
# Settings (environment): SIZE, SECONDS, THREADS, LARGE_STEPS, SEEDS, LOG_EVERY;
# SPP renders MLT for that many mutations per pixel instead of SECONDS (the
# quick mode: its chains then run steps however slow the machine).
set -eu
BIN=${1:-build/smallmlt}
SCENE=tiny-caustic
SIZE=${SIZE:-128}
SECONDS_=${SECONDS:-40}
THREADS=${THREADS:-4096}
LARGE_STEPS=${LARGE_STEPS:-0.05 0.1 0.3 0.5}
SEEDS=${SEEDS:-1 2 3}
LOG_EVERY=${LOG_EVERY:-1}
OUT=${RESULTS:-bench/results}/stuck
mkdir -p "$OUT"
ref=$(sh bench/reference.sh "$BIN" "$SCENE" "$SIZE")
csv="$OUT/error.csv"
echo "method,seed,seconds,samples_per_pixel,samples,mse,rel_mse,mse_unlit,block8_mse,block32_mse" > "$csv"
echo "large_step,seed,chains,steps,stuck_chains,longest_run" > "$OUT/stuck.csv"
common="scenes/$SCENE.scene --width $SIZE --height $SIZE --reference $ref --reference-mask ${ref%.pfm}-mask.pfm"
mlt_work="--time $SECONDS_"
[ -n "${SPP:-}" ] && mlt_work="--spp $SPP"
for seed in $SEEDS; do
    "$BIN" render $common --time "$SECONDS_" --method pt --seed "$seed" --quiet --log "$OUT/log.csv" \
        --log-every "$LOG_EVERY" --out "$OUT/pt-s$seed.png"
    tail -n +2 "$OUT/log.csv" | sed "s/^/pt,$seed,/" >> "$csv"
    for p in $LARGE_STEPS; do
        "$BIN" render $common $mlt_work --threads "$THREADS" --split visible --large-step "$p" --seed "$seed" \
            --log "$OUT/log.csv" --log-every "$LOG_EVERY" --out "$OUT/mlt-p$p-s$seed.png" \
            2> /dev/null > "$OUT/summary.txt"
        tail -n +2 "$OUT/log.csv" | sed "s/^/mlt-p$p,$seed,/" >> "$csv"
        # "4096 chains x 1 proposals x 2413 steps ... longest run of rejections 2102,
        # 5 chains stuck (1000 in a row)"
        sed -n 's/.* \([0-9]*\) chains x [0-9]* proposals x \([0-9]*\) steps.*longest run of rejections \([0-9]*\), \([0-9]*\) chains stuck.*/\1,\2,\4,\3/p' \
            "$OUT/summary.txt" | sed "s/^/$p,$seed,/" >> "$OUT/stuck.csv"
    done
done
rm -f "$OUT/log.csv" "$OUT/summary.txt"
first=$(echo "$SEEDS" | awk '{print $1}')
awk -F, -v s="$first" 'NR == 1 || $2 == s' "$csv" | cut -d, -f1,3,6 > "$OUT/error-seed$first.csv"
set -- "pt=PT"
for p in $LARGE_STEPS; do set -- "$@" "mlt-p$p=MLT, large step $p"; done
sh bench/plot_error.sh "$OUT/error-seed$first.csv" "$OUT/error.png" \
    "$SCENE ${SIZE}x$SIZE, $THREADS MLT threads, seed $first" "$@"
awk -F, -v scene="$SCENE" -f bench/median.awk -f bench/time_to_error.awk "$csv" > "$OUT/time_to_error.csv"
echo "time to reach PT's error at $SECONDS_ s by each metric (ratio < 1: faster than PT; medians over seeds $SEEDS):"
column -s, -t "$OUT/time_to_error.csv"
echo "stuck chains (a run of rejections of the default length or more) at the end of each render:"
column -s, -t "$OUT/stuck.csv"
echo "wrote $OUT/error.png"
