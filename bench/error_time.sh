#!/bin/sh
# Error against time for every method on the scenes where they differ: one
# render per (scene, method, seed) with a convergence log (render --log;
# MSE, relative MSE, MSE without the directly visible lights (mse_unlit, by
# the reference's mask) and MSE of 8x8 block means on linear RGB against a
# long PT reference, measuring not counted as render time). Charts one
# seed's MSE curves per scene (log-log) and prints, for each method and
# metric, the time it needs to reach PT's final error, as a ratio of PT's
# time (medians over the seeds; bench/time_to_error.awk).
# Writes bench/results/error_time/. Usage: bench/error_time.sh [BIN]
# Settings (environment): SCENES, SIZE, SECONDS, SEEDS, LOG_EVERY, THREADS, METHODS
# (those of flags() below: -eF is --omc-effort F, -pP --large-step P,
# mlt-strataN --strata N);
# PLOT_ONLY=1 redraws the charts and the table from the last run's CSVs.
set -eu
BIN=${1:-build/smallmlt}
SCENES=${SCENES:-cornell cornell-water cornell-glass ajar}
SIZE=${SIZE:-128}
SECONDS_=${SECONDS:-30}
SEEDS=${SEEDS:-1 2 3}
LOG_EVERY=${LOG_EVERY:-0.5}
THREADS=${THREADS:-auto}
OUT=${RESULTS:-bench/results}/error_time
mkdir -p "$OUT"

# method name and its flags; -eF: --omc-effort F
flags() {
    case $1 in
    pt) echo "--method pt" ;;
    mlt-none) echo "--method mlt --split none --burn-in none --large-step 0.5 --threads $THREADS" ;;
    mlt-nosplit) echo "--method mlt --split none --threads $THREADS" ;;
    mlt-visible) echo "--method mlt --split visible --threads $THREADS" ;;
    mlt-direct) echo "--method mlt --split direct --threads $THREADS" ;;
    mlt-direct-e*) echo "--method mlt --split direct --omc-effort ${1#mlt-direct-e} --threads $THREADS" ;;
    mlt) echo "--method mlt --threads $THREADS" ;;
    mlt-e*) echo "--method mlt --omc-effort ${1#mlt-e} --threads $THREADS" ;;
    mlt-2stage) echo "--method mlt --target two-stage --threads $THREADS" ;;
    mlt-kelemen) echo "--method mlt --weights kelemen --threads $THREADS" ;;
    mlt-kelemen-p*) echo "--method mlt --weights kelemen --large-step ${1#mlt-kelemen-p} --threads $THREADS" ;;
    mlt-strata) echo "--method mlt --strata auto --threads $THREADS" ;;
    mlt-strata*) echo "--method mlt --strata ${1#mlt-strata} --threads $THREADS" ;;
    mlt-k2) echo "--method mlt --proposals 2 --threads $THREADS" ;;
    mlt-k4) echo "--method mlt --proposals 4 --threads $THREADS" ;;
    *) echo "error_time.sh: unknown method $1" >&2; exit 2 ;;
    esac
}
METHODS=${METHODS:-pt mlt-nosplit mlt-direct mlt mlt-k2 mlt-k4}

echo "device: $("$BIN" devices | sed -n '1p'), cores: $(nproc)" | tee "$OUT/machine.txt"
echo "scene,method,mse_ratio,rel_mse_ratio,mse_unlit_ratio,block8_mse_ratio,block32_mse_ratio,pt_seconds,target_mse" > "$OUT/time_to_error.csv"
for scene in $SCENES; do
    ref=$(sh bench/reference.sh "$BIN" "$scene" "$SIZE")
    csv="$OUT/$scene.csv"
    [ -n "${PLOT_ONLY:-}" ] || echo "method,seed,seconds,samples_per_pixel,samples,mse,rel_mse,mse_unlit,block8_mse,block32_mse" > "$csv"
    run_seeds=$SEEDS
    [ -z "${PLOT_ONLY:-}" ] || run_seeds=""
    for seed in $run_seeds; do
        for m in $METHODS; do
            # shellcheck disable=SC2046
            "$BIN" render "scenes/$scene.scene" $(flags "$m") --width "$SIZE" --height "$SIZE" \
                --time "$SECONDS_" --seed "$seed" --quiet --reference "$ref" \
                --reference-mask "${ref%.pfm}-mask.pfm" --log "$OUT/log.csv" --log-every "$LOG_EVERY" --out "$OUT/$scene-$m-s$seed.png"
            tail -n +2 "$OUT/log.csv" | sed "s/^/$m,$seed,/" >> "$csv"
        done
    done
    rm -f "$OUT/log.csv"
    first=$(echo "$SEEDS" | awk '{print $1}')
    awk -F, -v s="$first" 'NR == 1 || $2 == s' "$csv" | cut -d, -f1,3,6 > "$OUT/$scene-seed$first.csv"
    sh bench/plot_error.sh "$OUT/$scene-seed$first.csv" "$OUT/$scene.png" \
        "$scene ${SIZE}x$SIZE, seed $first (reference: PT, $(sed -n 's/.* \([0-9]* spp\).*/\1/p' "${ref%.pfm}.txt"))" \
        "pt=PT" "mlt-none=MLT, no burn-in, no split, large step 0.5" \
        "mlt-nosplit=MLT, OMC burn-in, no split" "mlt-visible=MLT, split visible" \
        "mlt-direct=MLT, split direct" "mlt=MLT, split auto (default)" \
        "mlt-2stage=MLT, split auto, two-stage target" \
        "mlt-kelemen=MLT, split auto, Kelemen weights" \
        "mlt-kelemen-p0.3=MLT, Kelemen weights, large step 0.3" \
        "mlt-k2=split-transition K = 2" "mlt-k4=split-transition K = 4" \
        "mlt-strata=MLT, split auto, strata auto" "mlt-strata8=MLT, split auto, strata of 8"
    awk -F, -v scene="$scene" -f bench/median.awk -f bench/time_to_error.awk "$csv" >> "$OUT/time_to_error.csv"
done
echo
echo "time to reach the error every PT render reached at $SECONDS_ s, by each metric, ${SIZE}x$SIZE,"
echo "as a ratio of PT's time, medians over seeds ($SEEDS); pt_seconds and target_mse: by MSE;"
echo "ratio < 1: faster than PT; * = not reached, extrapolated as error ~ 1/t from the last row"
column -s, -t "$OUT/time_to_error.csv"
