#!/bin/sh
# The convergence log (render --reference --log): its last row's errors are
# the errors `compare` computes from the final image file, for PT and MLT,
# with and without --reference-mask (a depth-0 render: the lights seen
# directly); rows are ordered in time and samples; bad uses are refused
# without output.
# Usage: log_test.sh BIN
set -u
BIN=$1
DIR=build/test-scratch/log
rm -rf "$DIR" && mkdir -p "$DIR"
. test/checks.sh

film="--width 32 --height 32"
"$BIN" render scenes/cornell.scene $film --method pt --spp 64 --seed 99 --quiet --out "$DIR/ref.pfm"

# same_error LOG IMAGE [MASK]: each error of the log's last row, by the
# header's names, equals compare's (6 significant digits printed, so
# agreement to 1e-5 relative); mse_unlit only with MASK, else an empty field.
same_error() {
    { head -n 1 "$1"; tail -n 1 "$1"; "$BIN" compare "$2" "$DIR/ref.pfm" ${3:+--mask "$3"}; } |
        awk -v want="${3:+5}" 'NR == 1 { n = split($0, name, ",") }
        NR == 2 { split($0, row, ",") }
        NR == 3 { for (i = 1; i < NF; i += 2) got[$i] = $(i + 1) }
        END {
            for (i = 4; i <= n; ++i) {
                k = name[i]
                if (!(k in got)) { bad = bad || row[i] != ""; continue }
                d = row[i] - got[k]
                bad = bad || !(d * d <= 1e-10 * got[k] * got[k] && got[k] > 0)
                ++same
            }
            exit bad || same != (want ? want : 4)
        }'
}

# ordered LOG: seconds and samples strictly increase from row to row
ordered() {
    awk -F, 'NR > 2 && ($1 <= s || $3 <= n) {bad = 1} NR > 1 {s = $1; n = $3} END {exit bad || NR < 3}' "$1"
}

check mask_depth_0 0 "32x32, depth 0, pt" -- "$BIN" render scenes/cornell.scene $film --method pt \
    --depth 0 --spp 16 --out "$DIR/mask.pfm"
for m in pt mlt; do
    check "log_$m" 0 "error against $DIR/ref.pfm: mse" -- "$BIN" render scenes/cornell.scene $film \
        --method "$m" --threads 256 --spp 24 --reference "$DIR/ref.pfm" --reference-mask "$DIR/mask.pfm" \
        --log "$DIR/$m.csv" --log-every 0.01 --out "$DIR/$m.pfm"
    truth "log_${m}_header" grep -qx "seconds,samples_per_pixel,samples,mse,rel_mse,mse_unlit,block8_mse,block32_mse" "$DIR/$m.csv"
    truth "log_${m}_last_row_is_final_image" same_error "$DIR/$m.csv" "$DIR/$m.pfm" "$DIR/mask.pfm"
    truth "log_${m}_rows_ordered" ordered "$DIR/$m.csv"
done
# The mask leaves out the light, the noisiest pixels, and keeps the rest.
truth log_mask_leaves_out_the_light awk -F, 'END { exit !($6 > 0 && $6 < $4 / 2) }' "$DIR/pt.csv"
check log_no_mask 0 "block32_mse" -- "$BIN" render scenes/cornell.scene $film --method pt --spp 8 \
    --reference "$DIR/ref.pfm" --log "$DIR/nomask.csv" --log-every 0.01 --out "$DIR/nomask.pfm"
truth log_no_mask_empty_field same_error "$DIR/nomask.csv" "$DIR/nomask.pfm"
check log_without_reference 2 "--log $DIR/x.csv: give --reference" -- "$BIN" render scenes/cornell.scene --log "$DIR/x.csv"
check reference_png 2 "--reference $DIR/ref.png: a reference holds linear radiance" -- "$BIN" render scenes/cornell.scene --reference "$DIR/ref.png"
check reference_size 1 "--reference $DIR/ref.pfm: image is 32x32, the film 16x16" -- "$BIN" render scenes/cornell.scene --width 16 --height 16 --reference "$DIR/ref.pfm" --log "$DIR/size.csv" --out "$DIR/size.png"
absent reference_size_no_image "$DIR/size.png"
absent reference_size_no_log "$DIR/size.csv"
check reference_missing 1 "nope.pfm: cannot open image" -- "$BIN" render scenes/cornell.scene --reference "$DIR/nope.pfm"
check log_dir 2 "--log $DIR/no/x.csv: directory" -- "$BIN" render scenes/cornell.scene --reference "$DIR/ref.pfm" --log "$DIR/no/x.csv"
check reference_mask_without_reference 2 "--reference-mask $DIR/mask.pfm: give --reference" -- "$BIN" render scenes/cornell.scene --reference-mask "$DIR/mask.pfm"
check reference_mask_png 2 "--reference-mask $DIR/mask.png: a mask holds linear radiance" -- "$BIN" render scenes/cornell.scene --reference "$DIR/ref.pfm" --reference-mask "$DIR/mask.png"
"$BIN" render scenes/cornell.scene --method pt --width 16 --height 16 --depth 0 --spp 1 --quiet --out "$DIR/mask16.pfm"
check reference_mask_size 1 "--reference-mask $DIR/mask16.pfm: image is 16x16, the film 32x32" -- "$BIN" render scenes/cornell.scene $film --reference "$DIR/ref.pfm" --reference-mask "$DIR/mask16.pfm" --log "$DIR/masksize.csv" --out "$DIR/masksize.png"
absent reference_mask_size_no_image "$DIR/masksize.png"
absent reference_mask_size_no_log "$DIR/masksize.csv"
check log_every 2 "--log-every: '0' is not a positive number of seconds" -- "$BIN" render scenes/cornell.scene --log-every 0
no_temporaries "$DIR"
summary log
