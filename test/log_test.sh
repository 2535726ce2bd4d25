#!/bin/sh
# The convergence log (render --reference --log): its last row's error is the
# error `compare` computes from the final image file, for PT and MLT; rows
# are ordered in time and samples; bad uses are refused without output.
# Usage: log_test.sh BIN
set -u
BIN=$1
DIR=build/test-scratch/log
rm -rf "$DIR" && mkdir -p "$DIR"
. test/checks.sh

film="--width 32 --height 32"
"$BIN" render scenes/cornell.scene $film --method pt --spp 64 --seed 99 --quiet --out "$DIR/ref.pfm"

# same_error NAME LOG IMAGE: the log's last mse and rel_mse equal compare's
# (compare prints 6 significant digits, so agreement to 1e-5 relative).
same_error() {
    last=$(tail -n 1 "$2")
    got=$("$BIN" compare "$3" "$DIR/ref.pfm")
    echo "$last" "$got" | awk -F'[ ,]' '{
        d1 = $4 - $7; d2 = $5 - $9
        exit !(d1 * d1 <= 1e-10 * $7 * $7 && d2 * d2 <= 1e-10 * $9 * $9 && $7 > 0)
    }'
}

# ordered LOG: seconds and samples strictly increase from row to row
ordered() {
    awk -F, 'NR > 2 && ($1 <= s || $3 <= n) {bad = 1} NR > 1 {s = $1; n = $3} END {exit bad || NR < 3}' "$1"
}

for m in pt mlt; do
    check "log_$m" 0 "error against $DIR/ref.pfm: mse" -- "$BIN" render scenes/cornell.scene $film \
        --method "$m" --threads 256 --spp 24 --reference "$DIR/ref.pfm" --log "$DIR/$m.csv" \
        --log-every 0.01 --out "$DIR/$m.pfm"
    truth "log_${m}_header" grep -qx "seconds,samples_per_pixel,samples,mse,rel_mse" "$DIR/$m.csv"
    truth "log_${m}_last_row_is_final_image" same_error "$m" "$DIR/$m.csv" "$DIR/$m.pfm"
    truth "log_${m}_rows_ordered" ordered "$DIR/$m.csv"
done
check log_without_reference 2 "--log $DIR/x.csv: give --reference" -- "$BIN" render scenes/cornell.scene --log "$DIR/x.csv"
check reference_png 2 "--reference $DIR/ref.png: a reference holds linear radiance" -- "$BIN" render scenes/cornell.scene --reference "$DIR/ref.png"
check reference_size 1 "--reference $DIR/ref.pfm: image is 32x32, the film 16x16" -- "$BIN" render scenes/cornell.scene --width 16 --height 16 --reference "$DIR/ref.pfm" --log "$DIR/size.csv" --out "$DIR/size.png"
absent reference_size_no_image "$DIR/size.png"
absent reference_size_no_log "$DIR/size.csv"
check reference_missing 1 "nope.pfm: cannot open image" -- "$BIN" render scenes/cornell.scene --reference "$DIR/nope.pfm"
check log_dir 2 "--log $DIR/no/x.csv: directory" -- "$BIN" render scenes/cornell.scene --reference "$DIR/ref.pfm" --log "$DIR/no/x.csv"
check log_every 2 "--log-every: '0' is not a positive number of seconds" -- "$BIN" render scenes/cornell.scene --log-every 0
no_temporaries "$DIR"
summary log
