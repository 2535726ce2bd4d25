#!/bin/sh
# Runs every test: the GoogleTest binary and, beside it, the shell tests
# (test/*_test.sh, one after another), then prints the combined count as
# "N passed, N failed". The two run at once because much of the GoogleTest
# run is single-threaded (kernel builds); each shell test's output is shown
# after the GoogleTest output, from its log.
# Usage: run_all.sh TEST_BINARY  (with SMALLMLT_BIN naming the smallmlt binary)
set -u
TEST_BIN=$1
BIN=${SMALLMLT_BIN:-build/smallmlt}
LOG=build/test-scratch/gtest.log
mkdir -p build/test-scratch
(
    for t in test/*_test.sh; do
        name=$(basename "$t" _test.sh)
        sh "$t" "$BIN" > "build/test-scratch/$name.log" 2>&1
    done
) &
shell_pid=$!
"$TEST_BIN" 2>&1 | tee "$LOG"
gtest_rc=$?
wait "$shell_pid"
g_pass=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$LOG" | tail -n 1)
g_fail=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$LOG" | tail -n 1)
s_pass=0
s_fail=0
for t in test/*_test.sh; do
    name=$(basename "$t" _test.sh)
    cat "build/test-scratch/$name.log"
    line=$(grep "^$name: [0-9]* passed, [0-9]* failed$" "build/test-scratch/$name.log")
    # A script that stops before its summary counts as a failure.
    if [ -z "$line" ]; then s_fail=$((s_fail + 1)); continue; fi
    s_pass=$((s_pass + $(echo "$line" | awk '{print $2}')))
    s_fail=$((s_fail + $(echo "$line" | awk '{print $4}')))
done
passed=$(( ${g_pass:-0} + s_pass ))
failed=$(( ${g_fail:-0} + s_fail ))
# A crashed test binary reports no counts: count it as a failure.
if [ "$gtest_rc" -ne 0 ] && [ "${g_fail:-0}" -eq 0 ]; then failed=$((failed + 1)); fi
echo "all: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
