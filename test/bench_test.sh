#!/bin/sh
# The benchmark suite runs end to end: `bench/all.sh` in its quick mode (what
# `make bench-quick` runs), with results and references kept under
# build/test-scratch. Checks the shape of what it writes, never its speed.
# Usage: bench_test.sh BIN
set -u
BIN=$1
DIR=build/test-scratch/bench
rm -rf "$DIR" && mkdir -p "$DIR"
. test/checks.sh

QUICK=1 RESULTS="$DIR/results" CACHE="$DIR/cache" sh bench/all.sh "$BIN" > "$DIR/all.log" 2>&1
rc=$?
truth bench_quick_exit_0 [ "$rc" -eq 0 ]
R=$DIR/results

# rows FILE N: FILE has N lines after its header
rows() { [ "$(tail -n +2 "$1" | wc -l)" -eq "$2" ]; }
# png FILE: a PNG image
png() { [ "$(head -c 4 "$1" | tail -c 3)" = PNG ]; }

truth time_to_error_rows rows "$R/error_time/time_to_error.csv" 10
truth time_to_error_pt_is_1 awk -F, 'NR > 1 && $2 == "pt" && $3 != "1.000" {exit 1}' "$R/error_time/time_to_error.csv"
truth time_to_error_numbers awk -F, 'NR > 1 && !($3 + 0 > 0 && $4 + 0 > 0 && $6 + 0 > 0) {exit 1}' "$R/error_time/time_to_error.csv"
for scene in cornell cornell-water; do
    truth "log_methods_$scene" [ "$(cut -d, -f1 "$R/error_time/$scene.csv" | tail -n +2 | sort -u | tr '\n' ' ')" = "mlt mlt-k2 mlt-k4 mlt-none pt " ]
    truth "chart_$scene" png "$R/error_time/$scene.png"
done
truth threads_rows rows "$R/threads/threads.csv" 4
truth memory_rows rows "$R/memory/k1.csv" 24
truth burnin_rows rows "$R/burnin/error.csv" 6
truth proposals_rows rows "$R/proposals/error.csv" 6
truth stuck_error_methods [ "$(cut -d, -f1 "$R/stuck/error.csv" | tail -n +2 | sort -u | tr '\n' ' ')" = "mlt-p0.1 mlt-p0.5 pt " ]
truth stuck_counts_rows rows "$R/stuck/stuck.csv" 2
truth ranks_rows awk -F, 'NR > 1 && $2 > 0 && $3 > 0 && $4 > 0 {n++} END {exit n != 3}' "$R/ranks/summary.csv"
truth film_atomics_row awk -F, 'NR == 2 && $1 == 16 && $2 == "cornell" && $3 > 0 && $4 > 0 && $5 > 0 {ok = 1} END {exit !ok}' "$R/film_atomics/summary.csv"
truth stuck_counts_numbers awk -F, 'NR > 1 && !($3 > 0 && $4 > 0 && $5 >= 0 && $6 >= 0 && $5 <= $3) {exit 1}' "$R/stuck/stuck.csv"
for f in stuck/error.png threads/threads.png memory/memory.png burnin/figure1.png burnin/error.png proposals/crops.png proposals/error.png; do
    truth "chart_$f" png "$R/$f"
done
[ "$fail" -eq 0 ] || tail -n 20 "$DIR/all.log"
summary bench
