#!/bin/sh
# Every entry of test/mutants.txt still applies: its `from` text occurs
# exactly once in its file (`sh test/mutants.sh --check`, which builds and
# runs nothing), so that `make mutants` tests the bugs it lists; the check
# names an entry that does not apply, and skips the one a mutant's
# whole-suite run has applied (MUTANT_APPLIED).
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

# A whole-suite run of a mutant names it: its text is gone on purpose.
check skips_the_entry_applied 0 "mutants: 0 entries, 0 do not apply" -- \
    env MUTANTS_LIST="$stale" MUTANT_APPLIED=stale sh test/mutants.sh --check

summary mutants
