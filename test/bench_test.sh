#!/bin/sh
# The benchmark suite runs end to end: `bench/all.sh` in its quick mode (what
# `make bench-quick` runs), with results and references kept under
# build/test-scratch. Checks the shape of what it writes, never its speed;
# and bench/time_to_error.awk on a log made by hand.
# Usage: bench_test.sh BIN
set -u
BIN=$1
DIR=build/test-scratch/bench
rm -rf "$DIR" && mkdir -p "$DIR"
. test/checks.sh

# Two seeds of PT and of x. Targets (PT's largest final value): 0.2, and 0.02
# for mse_unlit; PT reaches them at 2 s and 4 s, median 3 s. x by mse: 1 s,
# and log-log between (1 s, 0.8) and (4 s, 0.05): 2 s, so 1.5 / 3; rel_mse:
# seed 1 never, 2 s x 0.4 / 0.2 = 4 s (*), seed 2 1 s, so 2.5 / 3; mse_unlit:
# 1 s twice; block8_mse: 1 s, and 4 s x 0.8 / 0.2 = 16 s (*), so 8.5 / 3;
# block32_mse (PT's as its block8_mse): 1 s, and 4 s x 0.4 / 0.2 = 8 s (*),
# so 4.5 / 3.
cat > "$DIR/hand.csv" << 'EOF'
method,seed,seconds,samples_per_pixel,samples,mse,rel_mse,mse_unlit,block8_mse,block32_mse
pt,1,1,1,1,0.4,0.4,0.04,0.4,0.4
pt,1,2,2,2,0.2,0.2,0.02,0.2,0.2
pt,1,4,4,4,0.1,0.1,0.01,0.1,0.1
pt,2,1,1,1,0.8,0.8,0.08,0.8,0.8
pt,2,2,2,2,0.4,0.4,0.04,0.4,0.4
pt,2,4,4,4,0.2,0.2,0.02,0.2,0.2
x,1,1,1,1,0.1,0.4,0.01,0.2,0.1
x,1,2,2,2,0.1,0.4,0.01,0.2,0.1
x,2,1,1,1,0.8,0.1,0.01,0.8,0.8
x,2,4,4,4,0.05,0.1,0.01,0.8,0.4
EOF
# time_to_error CSV: its rows for scene h, on one line
time_to_error() { awk -F, -v scene=h -f bench/median.awk -f bench/time_to_error.awk "$1" | tr '\n' ' '; }
check time_to_error_by_hand 0 "h,pt,1.000,1.000,1.000,1.000,1.000,3.00,0.2 h,x,0.500,0.833*,0.333,2.833*,1.500*,3.00,0.2 " -- time_to_error "$DIR/hand.csv"
# Without a mask, mse_unlit is an empty field, and so is its ratio.
awk -F, -v OFS=, 'NR > 1 { $8 = "" } 1' "$DIR/hand.csv" > "$DIR/nomask.csv"
check time_to_error_without_mask 0 "h,pt,1.000,1.000,,1.000,1.000,3.00,0.2 h,x,0.500,0.833*,,2.833*,1.500*,3.00,0.2 " -- time_to_error "$DIR/nomask.csv"

# bench/ideal_mse.py on 2x1 PFMs made by hand (little-endian floats): the
# reference has grey pixels of 1 and 3; M = 1 puts 2 mutations over a
# luminance of 4, so the ideal variances are 1 x 4 / (2 x 1) = 2 and
# 9 x 4 / (2 x 3) = 6, mean 4. With the second pixel lit in the mask, both
# go to the first: 1 x 1 / (2 x 1) = 0.5, and the image, off by 0.5 there,
# has an mse_unlit of 0.25, half the ideal.
f1='\000\000\200\077' f3='\000\000\100\100' f15='\000\000\300\077' f35='\000\000\140\100'
pfm() { printf 'PF\n2 1\n-1\n'; for v in "$@"; do printf "$v$v$v"; done; }
pfm "$f1" "$f3" > "$DIR/ideal_ref.pfm"
pfm "$f15" "$f35" > "$DIR/ideal_img.pfm"
pfm '\000\000\000\000' "$f1" > "$DIR/ideal_mask.pfm"
truth ideal_mse_by_hand [ "$(python3 bench/ideal_mse.py "$DIR/ideal_ref.pfm" 1)" = "ideal independent MLT at 1 mutations per pixel: mse 4" ]
check ideal_mse_masked_by_hand 0 "ideal_img.pfm: mse_unlit 0.25, 0.50 times the ideal" -- python3 bench/ideal_mse.py --mask "$DIR/ideal_mask.pfm" "$DIR/ideal_ref.pfm" 1 "$DIR/ideal_img.pfm"
check ideal_mse_bad_count 1 "MUTATIONS_PER_PIXEL: 'x' is not a number" -- python3 bench/ideal_mse.py "$DIR/ideal_ref.pfm" x
printf 'PF\n2 one\n-1\n' > "$DIR/ideal_bad.pfm"
check ideal_mse_bad_header 1 "ideal_bad.pfm: the PFM's size or scale line is not numbers" -- python3 bench/ideal_mse.py "$DIR/ideal_bad.pfm" 1

# bench/error_by_luminance.py on the same kind of PFMs: the reference's
# pixels are 3 and 1, the image's 3.5 and 1. In two bins by luminance, the
# bright pixel is bin 1 with 3 / 4 of the light and all of the error: an MSE
# of 0.5^2 = 0.25.
pfm "$f3" "$f1" > "$DIR/lum_ref.pfm"
pfm "$f35" "$f1" > "$DIR/lum_img.pfm"
truth error_by_luminance_by_hand sh -c "python3 bench/error_by_luminance.py --bins 2 '$DIR/lum_ref.pfm' '$DIR/lum_img.pfm' | grep -q '^  1 3.0000-3.0000  75.0%  *2.500e-01 (100.0%)\$'"
check error_by_luminance_bad_bins 1 "--bins: expected a whole number" -- python3 bench/error_by_luminance.py --bins x "$DIR/lum_ref.pfm" "$DIR/lum_img.pfm"

# bench/seed_mse.py on 2x1 PFMs: method a renders (1, 3) and (3, 1), a
# sample variance of 2 in each pixel; method b (1.5, 2.5) and (2.5, 1.5),
# 0.5, a quarter of a's. The film is smaller than a block.
f25='\000\000\040\100'
mkdir -p "$DIR/seeds"
pfm "$f1" "$f3" > "$DIR/seeds/h-a-1.pfm"
pfm "$f3" "$f1" > "$DIR/seeds/h-a-2.pfm"
pfm "$f15" "$f25" > "$DIR/seeds/h-b-1.pfm"
pfm "$f25" "$f15" > "$DIR/seeds/h-b-2.pfm"
truth seed_mse_by_hand [ "$(python3 bench/seed_mse.py "$DIR/seeds" h a b | tail -n 1)" = "h b: 2 seeds, mse 0.5 (0.250), block8 -, block32 -" ]
check seed_mse_one_render 1 "h-c-*.pfm: 0 render(s), need 2 or more" -- python3 bench/seed_mse.py "$DIR/seeds" h a c

QUICK=1 RESULTS="$DIR/results" CACHE="$DIR/cache" sh bench/all.sh "$BIN" > "$DIR/all.log" 2>&1
rc=$?
truth bench_quick_exit_0 [ "$rc" -eq 0 ]
R=$DIR/results

# rows FILE N: FILE has N lines after its header
rows() { [ "$(tail -n +2 "$1" | wc -l)" -eq "$2" ]; }
# png FILE: a PNG image
png() { [ "$(head -c 4 "$1" | tail -c 3)" = PNG ]; }

truth time_to_error_rows rows "$R/error_time/time_to_error.csv" 12
truth time_to_error_header [ "$(head -n 1 "$R/error_time/time_to_error.csv")" = "scene,size,method,mse_ratio,rel_mse_ratio,mse_unlit_ratio,block8_mse_ratio,block32_mse_ratio,pt_seconds,target_mse" ]
truth time_to_error_pt_is_1 awk -F, 'NR > 1 && $3 == "pt" && $4 $5 $6 $7 $8 != "1.0001.0001.0001.0001.000" {exit 1}' "$R/error_time/time_to_error.csv"
truth time_to_error_numbers awk -F, 'NR > 1 && !($4 + 0 > 0 && $5 + 0 > 0 && $6 + 0 > 0 && $7 + 0 > 0 && $8 + 0 > 0 && $9 + 0 > 0 && $10 + 0 > 0) {exit 1}' "$R/error_time/time_to_error.csv"
# each scene at 32x32 and at its own film (512x512)
truth time_to_error_sizes [ "$(cut -d, -f2 "$R/error_time/time_to_error.csv" | tail -n +2 | sort -u | tr '\n' ' ')" = "32x32 512x512 " ]
truth stuck_time_to_error_numbers awk -F, '!($3 + 0 > 0 && $4 + 0 > 0 && $5 + 0 > 0 && $6 + 0 > 0 && $7 + 0 > 0) {exit 1}' "$R/stuck/time_to_error.csv"
# masks: every cached reference has its mask beside it
masks() { for f in "$DIR"/cache/*s.pfm; do [ -s "${f%.pfm}-mask.pfm" ] || return 1; done; }
truth reference_masks masks
for tag in cornell-32x32 cornell-water-32x32 cornell-512x512 cornell-water-512x512; do
    truth "log_methods_$tag" [ "$(cut -d, -f1 "$R/error_time/$tag.csv" | tail -n +2 | sort -u | tr '\n' ' ')" = "mlt mlt-strata pt " ]
    truth "chart_$tag" png "$R/error_time/$tag.png"
done
truth threads_rows rows "$R/threads/threads.csv" 4
truth memory_rows rows "$R/memory/k1.csv" 24
truth burnin_rows rows "$R/burnin/error.csv" 6
truth proposals_rows rows "$R/proposals/error.csv" 6
truth stuck_error_methods [ "$(cut -d, -f1 "$R/stuck/error.csv" | tail -n +2 | sort -u | tr '\n' ' ')" = "mlt-p0.1 mlt-p0.5 pt " ]
truth stuck_counts_rows rows "$R/stuck/stuck.csv" 2
# A check that needs MLT steps to run within the quick mode's few seconds:
# on Mesa's llvmpipe a mutation costs 12 times what it costs PoCL
# (doc/devices.md), the burn-in takes all of that time and a render gets
# few steps (at least the one that --time grants after it), so there they are
# skipped, and say so.
slow=
if "$BIN" devices | head -n 1 | grep -q llvmpipe; then
    slow="device 0 is llvmpipe: few MLT steps run in the quick mode's time"
fi
# needs_steps NAME COMMAND...: truth, or a skip with its reason on a slow device
needs_steps() {
    if [ -n "$slow" ]; then echo "skip $1: $slow"; else truth "$@"; fi
}
needs_steps ranks_rows awk -F, 'NR > 1 && $2 > 0 && $3 > 0 && $4 > 0 {n++} END {exit n != 3}' "$R/ranks/summary.csv"
# Where the device lacks 64-bit atomics, the bench says so instead.
if [ -f "$R/film_atomics/skipped" ]; then
    truth film_atomics_skip_names_why grep -q "lacks cl_khr_int64_base_atomics" "$R/film_atomics/skipped"
else
    truth film_atomics_row awk -F, 'NR == 2 && $1 == 16 && $2 == "cornell" && $3 > 0 && $4 > 0 && $5 > 0 {ok = 1} END {exit !ok}' "$R/film_atomics/summary.csv"
fi
# The stuck renders run a fixed number of mutations (SPP), so their chains step on any device.
truth stuck_counts_numbers awk -F, 'NR > 1 && !($3 > 0 && $4 > 0 && $5 >= 0 && $6 >= 0 && $5 <= $3) {exit 1}' "$R/stuck/stuck.csv"
for f in stuck/error.png threads/threads.png memory/memory.png burnin/figure1.png burnin/error.png proposals/crops.png proposals/error.png; do
    truth "chart_$f" png "$R/$f"
done
[ "$fail" -eq 0 ] || tail -n 20 "$DIR/all.log"
summary bench
