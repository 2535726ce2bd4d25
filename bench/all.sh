#!/bin/sh
# The benchmark suite (`make bench`): error against time for every method
# (bench/error_time.sh), throughput against thread count (threads.sh),
# memory against depth (memory.sh), the burn-in and split-transition image
# strips (burnin.sh, proposals.sh), stuck chains (stuck.sh), and throughput
# (throughput.sh, mlt_vs_pt.sh, film_atomics.sh), and ranks against one
# process (ranks.sh, smallmlt-mpi). Writes bench/results/ (or RESULTS); with
# PUBLISH=1 copies the charts to doc/img/. About an hour on 2 cores.
# QUICK=1 (`make bench-quick`) runs every part at toy sizes and times, in
# under 2 minutes, to check that the suite works, not to measure.
# Usage: bench/all.sh [BIN]
set -eu
BIN=${1:-build/smallmlt}
RESULTS=${RESULTS:-bench/results}
export RESULTS
mkdir -p "$RESULTS"
t0=$(date +%s)
step() { echo "== $* ($(($(date +%s) - t0)) s)"; }

if [ -n "${QUICK:-}" ]; then
    export REF_SECONDS=${REF_SECONDS:-2} THREADS=${THREADS:-1024}
    step error against time
    SCENES="cornell cornell-water" SIZES="32 film" SECONDS=1 SEEDS=1 LOG_EVERY=0.25 \
        sh bench/error_time.sh "$BIN"
    step throughput against threads
    SIZE=32 SPP=4 MAX_THREADS=2048 sh bench/threads.sh "$BIN" 1
    step memory against depth
    sh bench/memory.sh "$BIN"
    step burn-in strip
    SIZE=32 TIMES="0.5 1" SHOW="0.5 1" sh bench/burnin.sh "$BIN"
    step split-transition strip
    SIZE=32 TIMES="0.5 1" KS="1 2 4" sh bench/proposals.sh "$BIN"
    step stuck chains
    SIZE=32 SECONDS=1 SPP=64 SEEDS=1 LARGE_STEPS="0.1 0.5" LOG_EVERY=0.25 sh bench/stuck.sh "$BIN"
    step 32-bit against 64-bit film
    SIZES=16 SCENES=cornell SPP=4 RUNS=1 sh bench/film_atomics.sh "$BIN"
    step ranks against one process
    SIZE=16 SPP=1 TIMES=0.5 RUNS=1 sh bench/ranks.sh "$BIN"
else
    step error against time
    sh bench/error_time.sh "$BIN"
    step throughput against threads
    sh bench/threads.sh "$BIN"
    step memory against depth
    sh bench/memory.sh "$BIN"
    step burn-in strip
    sh bench/burnin.sh "$BIN"
    step split-transition strip
    sh bench/proposals.sh "$BIN"
    step stuck chains
    sh bench/stuck.sh "$BIN"
    step throughput
    sh bench/throughput.sh "$BIN" 5
    sh bench/mlt_vs_pt.sh "$BIN" 5
    step 32-bit against 64-bit film
    sh bench/film_atomics.sh "$BIN"
    step ranks against one process
    sh bench/ranks.sh "$BIN"
fi
step done
if [ -n "${PUBLISH:-}" ]; then
    for f in "$RESULTS"/error_time/*.png; do
        case $f in *-s[0-9]*.png) ;; *) cp "$f" "doc/img/error-$(basename "$f")" ;; esac
    done
    cp "$RESULTS/threads/threads.png" doc/img/threads.png
    cp "$RESULTS/memory/memory.png" doc/img/memory.png
    cp "$RESULTS/burnin/figure1.png" doc/img/burnin-figure1.png
    cp "$RESULTS/burnin/error.png" doc/img/burnin-error.png
    cp "$RESULTS/proposals/crops.png" doc/img/proposals-crops.png
    cp "$RESULTS/proposals/error.png" doc/img/proposals-error.png
    cp "$RESULTS/stuck/error.png" doc/img/stuck-error.png
    echo "copied the charts to doc/img/"
fi
