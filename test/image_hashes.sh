#!/bin/sh
# Prints the SHA-256 of a fixed set of renders: every scene, by path tracing
# (both samplers) and by MLT (the default, K = 4 proposals, without burn-in,
# without the split, with the split of direct light, expected weights, the
# 64-bit film, the two-stage target), at fixed seeds and sample counts.
# A change that must not change images (a refactoring) leaves this list the
# same; compare the lists before and after. Not part of `make test`.
# Usage: image_hashes.sh [SMALLMLT_BIN]  (from the repository root)
set -eu
BIN=${1:-build/smallmlt}
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
for scene in scenes/*.scene; do
    name=$(basename "$scene" .scene)
    while read -r tag opts; do
        out="$DIR/$name-$tag.pfm"
        # shellcheck disable=SC2086
        "$BIN" render "$scene" --quiet --width 48 --height 40 --seed 3 $opts --out "$out"
        printf '%s %s-%s\n' "$(sha256sum < "$out" | cut -c1-16)" "$name" "$tag"
    done <<LIST
pt-sobol --method pt --spp 8
pt-random --method pt --sampler random --spp 8
mlt --spp 8 --threads 512
mlt-k4 --spp 8 --threads 512 --proposals 4
mlt-no-burn-in --spp 8 --threads 512 --burn-in none
mlt-no-split --spp 8 --threads 512 --split none
mlt-direct --spp 8 --threads 512 --split direct
mlt-expected --spp 8 --threads 256 --weights expected --large-step 0.2 --burn-in-iters 4
mlt-film64 --spp 8 --threads 512 --film-atomics 64 --rr-by luminance
mlt-two-stage --spp 8 --threads 512 --target two-stage
LIST
done
