#!/bin/sh
# Prints the path of a long path-traced reference of SCENE at SIZE x SIZE,
# rendering it first if bench/cache/ does not hold it. Its sample count is
# recorded beside it (.txt). References are not in git.
# Usage: bench/reference.sh BIN SCENE SIZE [SECONDS]
set -eu
BIN=$1 SCENE=$2 SIZE=$3 SECONDS_=${4:-${REF_SECONDS:-300}}
mkdir -p bench/cache
ref="bench/cache/$SCENE-${SIZE}x$SIZE.pfm"
if [ ! -s "$ref" ]; then
    echo "rendering reference $ref (path tracing, $SECONDS_ s)" >&2
    "$BIN" render "scenes/$SCENE.scene" --method pt --width "$SIZE" --height "$SIZE" \
        --time "$SECONDS_" --seed 987654321 --out "$ref" > "bench/cache/$SCENE-${SIZE}x$SIZE.txt"
fi
echo "$ref"
