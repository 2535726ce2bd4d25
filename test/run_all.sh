#!/bin/sh
# Runs every test: the GoogleTest binary, as SHARDS shards at once (default
# 4: with 3 the last shard ended 20-40 s after the others), and beside them
# the shell tests (test/*_test.sh, one after another);
# then prints the combined count as "N passed, N failed". They run at once
# because much of a GoogleTest run is single-threaded (PoCL building
# kernels): shards keep both cores busy (on 2 cores with no kernel cached,
# two shards took 3 min 6 s against 3 min 57 s for one). The first shard's
# output is shown as it runs, the others' and each shell test's after, from
# their logs.
# Beside them runs the rusticl subset: RUSTICL_TESTS (a GoogleTest
# filter) on Mesa's OpenCL (llvmpipe), the compiler of Linux's small GPUs;
# where Mesa's OpenCL has no device here, it is skipped and says why.
# RUSTICL_TESTS=none leaves it out (`make test-rusticl` runs everything
# there instead).
# Usage: run_all.sh TEST_BINARY  (with SMALLMLT_BIN naming the smallmlt binary)
set -u
TEST_BIN=$1
BIN=${SMALLMLT_BIN:-build/smallmlt}
export SMALLMLT_BIN=$BIN
SCRATCH=build/test-scratch
mkdir -p "$SCRATCH"
rm -f "$SCRATCH"/gtest-*.rc "$SCRATCH"/gtest-*.log "$SCRATCH"/rusticl.*
# The layout probe, the loop limit and argument reads, furnaces, the
# sampling chi-square tests, a chain-target test, determinism (with many
# samples in one launch against one at a time: the loop limit's symptom),
# the film's overflow bound, the split's closed forms, the stuck count,
# the direct light and the emission the camera sees. The block-wise
# render tests take minutes on llvmpipe: `make test-rusticl` runs them.
RUSTICL_TESTS=${RUSTICL_TESTS-SharedLayout.*:OpenCl.*:Depths/Furnace.*:DiffuseSampling.*:\
LightSampling.*:DielectricSampling.*:LightPick.*:SmallStep.IntegerDelta*:SobolSampler.Every*:SobolSampler.ABounce*:\
SobolSampler.Pairs*:\
Proposals/ChainTarget.StatesFollowTheClosedFormMarginals/0:MltDeterminism.*:\
Render.SameSeed*:Render.ManySamplesAtOnceEqualOneByOne:FilmOverflow.*:\
Split.FurnacePartsAreTheClosedForm:StuckChains.EveryChainThatBecameStuckIsCountedOnce:DirectLight.*:\
EmissionSeen.MomentIsTheLightsImageOnTheFilm}
RUSTICL_ICD=/etc/OpenCL/vendors/rusticl.icd
rusticl() { OCL_ICD_VENDORS=$RUSTICL_ICD RUSTICL_ENABLE=swrast "$@"; }
if [ "$RUSTICL_TESTS" != none ]; then
    if ! rusticl "$BIN" devices 2>/dev/null | grep -q 'llvmpipe.*(rusticl)'; then
        echo "no llvmpipe device on Mesa's OpenCL ($RUSTICL_ICD; mesa-opencl-icd, make deps)" \
            > "$SCRATCH/rusticl.skip"
    else
        {
            rusticl "$TEST_BIN" --gtest_filter="$RUSTICL_TESTS" > "$SCRATCH/rusticl.log" 2>&1
            echo $? > "$SCRATCH/rusticl.rc"
        } &
    fi
fi
(
    for t in test/*_test.sh; do
        name=$(basename "$t" _test.sh)
        sh "$t" "$BIN" > "$SCRATCH/$name.log" 2>&1
    done
) &
SHARDS=${SHARDS:-4}
export GTEST_TOTAL_SHARDS=$SHARDS
for k in $(seq 1 $((SHARDS - 1))); do
    {
        GTEST_SHARD_INDEX=$k "$TEST_BIN" > "$SCRATCH/gtest-$k.log" 2>&1
        echo $? > "$SCRATCH/gtest-$k.rc"
    } &
done
{
    GTEST_SHARD_INDEX=0 "$TEST_BIN" 2>&1
    echo $? > "$SCRATCH/gtest-0.rc"
} | tee "$SCRATCH/gtest-0.log"
wait
g_pass=0
g_fail=0
g_skip=0
shard_failed=0
# count_gtest LOG RC_FILE: adds a GoogleTest run's counts.
count_gtest() {
    [ "$(cat "$2")" = 0 ] || shard_failed=1
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$1" | tail -n 1)
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$1" | tail -n 1)
    sk=$(sed -n 's/^\[  SKIPPED \] \([0-9]*\) test.*/\1/p' "$1" | tail -n 1)
    g_pass=$((g_pass + ${p:-0}))
    g_fail=$((g_fail + ${f:-0}))
    g_skip=$((g_skip + ${sk:-0}))
    # A crashed run reports no counts: count it as a failure.
    [ -z "$p$f" ] && g_fail=$((g_fail + 1))
}
for k in $(seq 0 $((SHARDS - 1))); do
    [ "$k" -gt 0 ] && cat "$SCRATCH/gtest-$k.log"
    count_gtest "$SCRATCH/gtest-$k.log" "$SCRATCH/gtest-$k.rc"
done
if [ -f "$SCRATCH/rusticl.skip" ]; then
    echo "rusticl subset: skipped: $(cat "$SCRATCH/rusticl.skip")"
    g_skip=$((g_skip + 1))
elif [ -f "$SCRATCH/rusticl.rc" ]; then
    echo "== the rusticl subset, on Mesa's OpenCL (llvmpipe)"
    cat "$SCRATCH/rusticl.log"
    count_gtest "$SCRATCH/rusticl.log" "$SCRATCH/rusticl.rc"
fi
s_pass=0
s_fail=0
for t in test/*_test.sh; do
    name=$(basename "$t" _test.sh)
    cat "$SCRATCH/$name.log"
    line=$(grep "^$name: [0-9]* passed, [0-9]* failed$" "$SCRATCH/$name.log")
    # A script that stops before its summary counts as a failure.
    if [ -z "$line" ]; then s_fail=$((s_fail + 1)); continue; fi
    s_pass=$((s_pass + $(echo "$line" | awk '{print $2}')))
    s_fail=$((s_fail + $(echo "$line" | awk '{print $4}')))
done
passed=$((g_pass + s_pass))
failed=$((g_fail + s_fail))
# A shard that exits non-zero without counting a failure still fails.
if [ "$shard_failed" -ne 0 ] && [ "$g_fail" -eq 0 ]; then failed=$((failed + 1)); fi
echo "all: $passed passed, $failed failed, $g_skip skipped"
[ "$failed" -eq 0 ]
