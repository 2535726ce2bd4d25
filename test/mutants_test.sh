#!/bin/sh
# Every entry of test/mutants.txt still applies: its `from` text occurs
# exactly once in its file (`sh test/mutants.sh --check`, which builds and
# runs nothing), so that `make mutants` tests the bugs it lists; and the
# check names an entry that does not apply.
# Usage: mutants_test.sh [SMALLMLT_BIN] (run from the repository root; the
# binary is not used)
. test/checks.sh
scratch=build/test-scratch
mkdir -p "$scratch"

check every_entry_applies 0 " 0 do not apply" -- sh test/mutants.sh --check

stale=$scratch/mutants-stale.txt
printf 'name: stale\nwhat: a bug in text that is gone\nfile: src/render/omc_cells.cpp\nfrom: text-that-is-nowhere\nto: x\nfirst: x\n' >"$stale"
check names_an_entry_that_does_not_apply 2 \
    "MUTANT stale: 'text-that-is-nowhere' occurs 0 times in src/render/omc_cells.cpp" -- \
    env MUTANTS_LIST="$stale" sh test/mutants.sh --check

summary mutants
