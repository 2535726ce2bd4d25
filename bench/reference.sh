#!/bin/sh
# Prints the path of a long path-traced reference of SCENE at SIZE x SIZE
# rendered for SECONDS (default 300, or REF_SECONDS), rendering it first if
# the cache (bench/cache/, or CACHE) does not hold it. Its render summary,
# with the sample count, is kept beside it (.txt), and so is its mask for
# render --reference-mask (-mask.pfm: a depth-0 PT render at 16 spp, which
# holds only the lights the camera sees directly). References are not in git.
# Usage: bench/reference.sh BIN SCENE SIZE [SECONDS]
set -eu
BIN=$1 SCENE=$2 SIZE=$3 SECONDS_=${4:-${REF_SECONDS:-300}}
CACHE=${CACHE:-bench/cache}
mkdir -p "$CACHE"
base="$CACHE/$SCENE-${SIZE}x$SIZE-${SECONDS_}s"
if [ ! -s "$base.pfm" ]; then
    echo "rendering reference $base.pfm (path tracing, $SECONDS_ s)" >&2
    "$BIN" render "scenes/$SCENE.scene" --method pt --width "$SIZE" --height "$SIZE" \
        --time "$SECONDS_" --seed 987654321 --out "$base.pfm" > "$base.txt"
fi
if [ ! -s "$base-mask.pfm" ]; then
    "$BIN" render "scenes/$SCENE.scene" --method pt --depth 0 --spp 16 --width "$SIZE" \
        --height "$SIZE" --seed 987654321 --quiet --out "$base-mask.pfm"
fi
echo "$base.pfm"
