#!/bin/sh
# Mitsuba 3 as a peer (bench/mitsuba_peer.py): sets up a virtual environment
# under bench/venv with the mitsuba and numpy wheels from PyPI and Debian's
# libllvm19 (for Mitsuba's LLVM back end), then, per scene file, checks that
# smallmlt's path tracer agrees with Mitsuba's path integrator within noise
# and measures both, and smallmlt's MLT, at equal time against a long
# reference. Writes bench/results/mitsuba/. Not part of `make test`.
# Usage: bench/mitsuba.sh [BIN] [SCENE.xml ... | cbox]  (cbox: Mitsuba's own
# Cornell box, mi.cornell_box(), written out as a scene file; default: every
# project scene and cbox)
# Settings (environment): THREADS (2), SIZE (128), SECONDS (10), REPLICAS (8),
# AGREE_SIZE (64), AGREE_SPP (256), REF_SECONDS (300), SEEDS (3: the
# equal-time figures are medians), EQUAL_TIME (1; 0: the agreement only),
# PEER_RINT (integral; mitsuba: leave roughplastic's inner reflectance as
# Mitsuba computes it; bench/mitsuba_peer.py says why).
set -eu
BIN=${1:-build/smallmlt}
shift 2>/dev/null || true
SCENES=${*:-$(ls scenes/*.xml) cbox}
VENV=bench/venv
LLVM=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1
if [ ! -e "$LLVM" ]; then
    echo "installing libllvm19 (Mitsuba's LLVM back end fails with Debian's default LLVM)"
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libllvm19 >/dev/null
fi
if [ ! -x "$VENV/bin/python" ]; then
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install -q mitsuba numpy
fi
export DRJIT_LIBLLVM_PATH="$LLVM"
exec "$VENV/bin/python" bench/mitsuba_peer.py "$BIN" $SCENES
