#!/bin/sh
# Error against time for every method on the scenes where they differ: one
# render per (scene, film size, method, seed) with a convergence log (render --log;
# MSE, relative MSE, MSE without the directly visible lights (mse_unlit, by
# the reference's mask) and MSE of 8x8 block means on linear RGB against a
# long PT reference, measuring not counted as render time). Charts one
# seed's MSE curves per scene (log-log) and prints, for each method and
# metric, the time it needs to reach PT's final error, as a ratio of PT's
# time (medians over the seeds; bench/time_to_error.awk), and crops the
# lower middle of the film from the reference and each method's first seed
# side by side at full size (SCENE-WxH-crops.png).
# Each scene at each of SIZES: N is an N x N film, `film` the scene's own
# (512x512 for most); files are named SCENE-WxH.
# Writes bench/results/error_time/. Usage: bench/error_time.sh [BIN]
# Settings (environment): SCENES, SIZES, SECONDS, SEEDS, LOG_EVERY, THREADS,
# METHODS (those of flags() below: -eF is --omc-effort F, -pP --large-step P,
# mlt-strataN --strata N, mlt-fsN --film-step N (mlt-fsfilm: film),
# mlt-psN --path-step N, mlt-rN --restart N), REF_SECONDS and
# REF_SECONDS_FILM (the references' time at N x N and at the scene's film;
# bench/reference.sh);
# PLOT_ONLY=1 redraws the charts and the table from the last run's CSVs.
set -eu
BIN=${1:-build/smallmlt}
SCENES=${SCENES:-cornell cornell-water cornell-glass ajar cornell-glossy tiny-caustic}
SIZES=${SIZES:-128 film}
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
    mlt-fs*) echo "--method mlt --film-step ${1#mlt-fs} --threads $THREADS" ;;
    mlt-ps*) echo "--method mlt --path-step ${1#mlt-ps} --threads $THREADS" ;;
    mlt-r*) echo "--method mlt --restart ${1#mlt-r} --threads $THREADS" ;;
    mlt-k2) echo "--method mlt --proposals 2 --threads $THREADS" ;;
    mlt-k4) echo "--method mlt --proposals 4 --threads $THREADS" ;;
    *) echo "error_time.sh: unknown method $1" >&2; exit 2 ;;
    esac
}
METHODS=${METHODS:-pt mlt mlt-strata}

echo "device: $("$BIN" devices | sed -n '1p'), cores: $(nproc)" | tee "$OUT/machine.txt"
echo "scene,size,method,mse_ratio,rel_mse_ratio,mse_unlit_ratio,block8_mse_ratio,block32_mse_ratio,pt_seconds,target_mse" > "$OUT/time_to_error.csv"
for scene in $SCENES; do
for size in $SIZES; do
    if [ "$size" = film ]; then
        dims=$(awk '$1 == "film" { print $2 "x" $3 }' "scenes/$scene.scene")
        size_flags=""
        ref=$(REF_SECONDS=${REF_SECONDS_FILM:-${REF_SECONDS:-300}} sh bench/reference.sh "$BIN" "$scene" film)
    else
        dims=${size}x$size
        size_flags="--width $size --height $size"
        ref=$(sh bench/reference.sh "$BIN" "$scene" "$size")
    fi
    tag=$scene-$dims
    csv="$OUT/$tag.csv"
    [ -n "${PLOT_ONLY:-}" ] || echo "method,seed,seconds,samples_per_pixel,samples,mse,rel_mse,mse_unlit,block8_mse,block32_mse" > "$csv"
    run_seeds=$SEEDS
    [ -z "${PLOT_ONLY:-}" ] || run_seeds=""
    for seed in $run_seeds; do
        for m in $METHODS; do
            # shellcheck disable=SC2046,SC2086
            "$BIN" render "scenes/$scene.scene" $(flags "$m") $size_flags \
                --time "$SECONDS_" --seed "$seed" --quiet --reference "$ref" \
                --reference-mask "${ref%.pfm}-mask.pfm" --log "$OUT/log.csv" --log-every "$LOG_EVERY" --out "$OUT/$tag-$m-s$seed.png"
            tail -n +2 "$OUT/log.csv" | sed "s/^/$m,$seed,/" >> "$csv"
        done
    done
    rm -f "$OUT/log.csv"
    first=$(echo "$SEEDS" | awk '{print $1}')
    awk -F, -v s="$first" 'NR == 1 || $2 == s' "$csv" | cut -d, -f1,3,6 > "$OUT/$tag-seed$first.csv"
    sh bench/plot_error.sh "$OUT/$tag-seed$first.csv" "$OUT/$tag.png" \
        "$scene $dims, seed $first (reference: PT, $(sed -n 's/.* \([0-9]* spp\).*/\1/p' "${ref%.pfm}.txt"))" \
        "pt=PT" "mlt-none=MLT, no burn-in, no split, large step 0.5" \
        "mlt-nosplit=MLT, OMC burn-in, no split" "mlt-visible=MLT, split visible" \
        "mlt-direct=MLT, split direct" "mlt=MLT, split auto (default)" \
        "mlt-2stage=MLT, split auto, two-stage target" \
        "mlt-kelemen=MLT, split auto, Kelemen weights" \
        "mlt-kelemen-p0.3=MLT, Kelemen weights, large step 0.3" \
        "mlt-k2=split-transition K = 2" "mlt-k4=split-transition K = 4" \
        "mlt-strata=MLT, split auto, strata auto" "mlt-strata8=MLT, split auto, strata of 8" \
        "mlt-strata32=MLT, split auto, strata of 32" \
        "mlt-fsfilm=MLT, film steps of a 64th of the film" "mlt-fs4=MLT, film steps of 4 pixels" "mlt-fs8=MLT, film steps of 8 pixels" \
        "mlt-fs16=MLT, film steps of 16 pixels" "mlt-ps64=MLT, path steps of a 64th, as Kelemen" \
        "mlt-r0=MLT, no restarts" "mlt-r8=MLT, restarts every 8 steps" \
        "mlt-r16=MLT, restarts every 16 steps" \
        "mlt-r32=MLT, restarts every 32 steps"
    # the lower middle of the film at full size (cornell-water's floor under
    # the water): the reference and each method at equal time, seed $first
    w=${dims%x*} h=${dims#*x} panels=$(($(echo "$METHODS" | wc -w) + 1))
    {
        echo "set terminal pngcairo size $((panels * (w / 2 + 24))),$((h / 2 + 40)) font ',10'"
        echo "set output '$OUT/$tag-crops.png'"
        echo "set multiplot layout 1,$panels"
        echo "unset border; unset tics; unset key; set size ratio -1"
        echo "set lmargin 1; set rmargin 1; set bmargin 0; set tmargin 2"
        echo "set xrange [$((w / 4)):$((3 * w / 4))]; set yrange [0:$((h / 2))]"
        echo "set title 'reference (PT)'"
        echo "plot '${ref%.pfm}.png' binary filetype=png with rgbimage"
        for m in $METHODS; do
            echo "set title '$m, $SECONDS_ s'"
            echo "plot '$OUT/$tag-$m-s$first.png' binary filetype=png with rgbimage"
        done
        echo "unset multiplot"
    } | gnuplot
    awk -F, -v scene="$scene,$dims" -f bench/median.awk -f bench/time_to_error.awk "$csv" >> "$OUT/time_to_error.csv"
done
done
echo
echo "time to reach the error every PT render reached at $SECONDS_ s, by each metric,"
echo "as a ratio of PT's time, medians over seeds ($SEEDS); pt_seconds and target_mse: by MSE;"
echo "ratio < 1: faster than PT; * = not reached, extrapolated as error ~ 1/t from the last row"
column -s, -t "$OUT/time_to_error.csv"
