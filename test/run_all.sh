#!/bin/sh
# Runs every test: the GoogleTest binary and the command-line checks, then
# prints the combined count as "N passed, N failed".
# Usage: run_all.sh TEST_BINARY  (with SMALLMLT_BIN naming the smallmlt binary)
set -u
TEST_BIN=$1
BIN=${SMALLMLT_BIN:-build/smallmlt}
LOG=build/test-scratch/gtest.log
mkdir -p build/test-scratch
"$TEST_BIN" 2>&1 | tee "$LOG"
gtest_rc=$?
g_pass=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$LOG" | tail -n 1)
g_fail=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$LOG" | tail -n 1)
sh test/cli_test.sh "$BIN" | tee build/test-scratch/cli.log
c_pass=$(sed -n 's/^cli: \([0-9]*\) passed.*/\1/p' build/test-scratch/cli.log)
c_fail=$(sed -n 's/^cli: [0-9]* passed, \([0-9]*\) failed/\1/p' build/test-scratch/cli.log)
passed=$(( ${g_pass:-0} + ${c_pass:-0} ))
failed=$(( ${g_fail:-0} + ${c_fail:-0} ))
# A crashed test binary reports no counts: count it as a failure.
if [ "$gtest_rc" -ne 0 ] && [ "${g_fail:-0}" -eq 0 ]; then failed=$((failed + 1)); fi
if [ -z "$c_pass" ]; then failed=$((failed + 1)); fi
echo "all: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
