#!/bin/sh
# Prints the path of a long path-traced reference of SCENE at SIZE x SIZE
# (SIZE `film`: at the scene's own film) rendered for SECONDS (default 300, or REF_SECONDS), rendering it first if
# the cache (bench/cache/, or CACHE) does not hold it. Its render summary,
# with the sample count, is kept beside it (.txt), and so is its mask for
# render --reference-mask (-mask.pfm: a depth-0 PT render at 16 spp, which
# holds only the lights the camera sees directly) and a PNG for figures
# (.png). References are not in git.
# Usage: bench/reference.sh BIN SCENE SIZE [SECONDS]
set -eu
BIN=$1 SCENE=$2 SIZE=$3 SECONDS_=${4:-${REF_SECONDS:-300}}
CACHE=${CACHE:-bench/cache}
mkdir -p "$CACHE"
if [ "$SIZE" = film ]; then
    base="$CACHE/$SCENE-film-${SECONDS_}s" size_flags=""
else
    base="$CACHE/$SCENE-${SIZE}x$SIZE-${SECONDS_}s" size_flags="--width $SIZE --height $SIZE"
fi
if [ ! -s "$base.pfm" ]; then
    echo "rendering reference $base.pfm (path tracing, $SECONDS_ s)" >&2
    # shellcheck disable=SC2086
    "$BIN" render "scenes/$SCENE.scene" --method pt $size_flags \
        --time "$SECONDS_" --seed 987654321 --out "$base.pfm" --out "$base.png" > "$base.txt"
fi
if [ ! -s "$base-mask.pfm" ]; then
    # shellcheck disable=SC2086
    "$BIN" render "scenes/$SCENE.scene" --method pt --depth 0 --spp 16 $size_flags \
        --seed 987654321 --quiet --out "$base-mask.pfm"
fi
echo "$base.pfm"
