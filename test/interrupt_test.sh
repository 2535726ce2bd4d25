#!/bin/sh
# Interrupted renders: SIGINT or SIGTERM ends the render after the current
# pass, writes a complete image and exits 3; a second SIGINT exits at once
# (130) leaving no half-written file. Each signal is sent once the render is
# known to be where the check wants it (its convergence log has a row, or it
# printed a line), so the outcome does not depend on timing.
# Usage: interrupt_test.sh BIN
set -u
BIN=$1
DIR=build/test-scratch/interrupt
rm -rf "$DIR" && mkdir -p "$DIR"
. test/checks.sh

film="--width 32 --height 32"
"$BIN" render scenes/cornell.scene $film --method pt --spp 4 --quiet --out "$DIR/ref.pfm"

# start NAME METHOD: a long render in the background, logging every pass;
# returns once its log has a row (the render loop is running)
start() {
    "$BIN" render scenes/cornell.scene $film --method "$2" --threads 1024 --time 600 --quiet \
        --reference "$DIR/ref.pfm" --log "$DIR/$1.csv" --log-every 0.01 \
        --out "$DIR/$1.pfm" --out "$DIR/$1.png" > "$DIR/$1.out" 2>&1 &
    pid=$!
    i=0
    while [ "$i" -lt 600 ] && ! cat "$DIR"/.tmp-*"$1.csv" 2>/dev/null | sed -n 2p | grep -q .; do
        sleep 0.1
        i=$((i + 1))
    done
}

for sig in INT TERM; do
    for m in pt mlt; do
        run="$m-$sig"
        start "$run" "$m"
        kill -"$sig" "$pid"
        wait "$pid"
        rc=$?
        truth "${run}_exit_3" [ "$rc" -eq 3 ]
        truth "${run}_says_so" grep -q "interrupted after" "$DIR/$run.out"
        check "${run}_image_readable" 0 "mse" -- "$BIN" compare "$DIR/$run.pfm" "$DIR/ref.pfm"
        truth "${run}_png_written" [ -s "$DIR/$run.png" ]
        truth "${run}_log_written" [ -s "$DIR/$run.csv" ]
    done
done

# Two signals: the second ends the process at once, even in the middle of
# a long burn-in that no pass boundary interrupts (4,096 rounds of 65,536
# paths: minutes). Each signal waits for a line the process prints: the
# first for "set up ...; rendering", after the kernel builds (the burn-in
# follows), the second for the first one's answer.
"$BIN" render scenes/cornell.scene $film --threads 65536 --burn-in-iters 4096 --spp 1 \
    --reference "$DIR/ref.pfm" --log "$DIR/twice.csv" --out "$DIR/twice.pfm" > "$DIR/twice.out" 2>&1 &
pid=$!
wait_for() { # FILE TEXT: until FILE holds TEXT (60 s at most)
    i=0
    while [ "$i" -lt 600 ] && ! grep -q "$2" "$1" 2>/dev/null; do sleep 0.1; i=$((i + 1)); done
}
wait_for "$DIR/twice.out" "; rendering"
kill -INT "$pid"
wait_for "$DIR/twice.out" "signal again to quit at once"
truth twice_running_at_second kill -INT "$pid"
wait "$pid"
rc=$?
truth twice_exit_130 [ "$rc" -eq 130 ]
absent twice_no_image "$DIR/twice.pfm"
absent twice_no_log "$DIR/twice.csv"
no_temporaries "$DIR"
summary interrupt
