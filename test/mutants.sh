#!/bin/sh
# `make mutants`: does the suite catch deliberate bugs? Copies the project to
# build/mutants/tree, then for each entry of test/mutants.txt (or only the
# names given) applies the bug, rebuilds, runs the entry's `first` tests and,
# if none fails, the whole suite (test/run_all.sh), and records whether some
# test failed. Writes build/mutants/report.md; exits 1 if a bug survived, 2
# if an entry no longer applies (its `from` text is not found exactly once)
# or its bug does not compile. With --check it builds and runs nothing: it
# only says whether every entry still applies (test/mutants_test.sh), but
# the one named by MUTANT_APPLIED, which the whole-suite run of that entry
# sets.
# Usage: sh test/mutants.sh [--check] [NAME...]
# (MUTANTS_LIST names another list than test/mutants.txt.)
set -u
ROOT=$(pwd)
LIST=${MUTANTS_LIST:-$ROOT/test/mutants.txt}
OUT=$ROOT/build/mutants
TREE=$OUT/tree
JOBS=${JOBS:-$(nproc)}
CHECK=
[ "${1-}" = --check ] && { CHECK=1; shift; }
if [ -z "$CHECK" ]; then
    mkdir -p "$OUT"
    rm -rf "$TREE"
    mkdir -p "$TREE"
    # The project as it is now, committed or not, without build outputs.
    git ls-files -co --exclude-standard -z | tar --null -T - -cf - | tar -xf - -C "$TREE"
    cd "$TREE" || exit 2
    echo "building the unmutated tree"
    make -s -j"$JOBS" all build/smallmlt_tests >"$OUT/build.log" 2>&1 ||
        { echo "the unmutated tree does not build (build/mutants/build.log)"; exit 2; }
fi

REPORT=$OUT/report.md
[ -n "$CHECK" ] || printf '| bug | file | result | tests that failed | seconds |\n| --- | --- | --- | --- | --- |\n' >"$REPORT"
survived=0
broken=0
total=0
start_all=$(date +%s)

# applies NAME FILE FROM: whether FROM occurs exactly once in FILE (else
# says so)
applies() {
    n=0
    [ -f "$2" ] && n=$(FROM=$3 perl -0ne 'BEGIN { $c = 0 } $c++ while /\Q$ENV{FROM}\E/g; END { print $c }' "$2")
    [ "$n" = 1 ] && return 0
    echo "MUTANT $1: '$3' occurs $n times in $2 (must be once)"
    return 1
}

# run_one NAME FILE FROM TO FIRST WHAT ENV
run_one() {
    name=$1 file=$2 from=$3 to=$4 first=$5 what=$6 menv=$7
    total=$((total + 1))
    t0=$(date +%s)
    cp "$ROOT/$file" "$file"
    if ! applies "$name" "$file" "$from"; then
        printf '| %s | %s | does not apply | | |\n' "$what" "$file" >>"$REPORT"
        broken=$((broken + 1))
        return
    fi
    FROM=$from TO=$to perl -0pi -e 's/\Q$ENV{FROM}\E/$ENV{TO}/' "$file"
    if ! make -s -j"$JOBS" all build/smallmlt_tests >"$OUT/$name.build.log" 2>&1; then
        echo "MUTANT $name: does not compile (build/mutants/$name.build.log)"
        printf '| %s | %s | does not compile | | |\n' "$what" "$file" >>"$REPORT"
        broken=$((broken + 1))
        cp "$ROOT/$file" "$file"
        return
    fi
    log=$OUT/$name.log
    result=survived
    # stdin from /dev/null: mpirun (test_mpi.cpp) would read the entry list.
    env $menv build/smallmlt_tests --gtest_filter="$first" >"$log" 2>&1 </dev/null || result=killed
    if [ "$result" = survived ]; then
        # MUTANT_APPLIED: the entry whose text this tree no longer holds, on
        # purpose, which the suite's check that every entry applies skips.
        MUTANT_APPLIED=$name SMALLMLT_BIN=build/smallmlt sh test/run_all.sh build/smallmlt_tests \
            >>"$log" 2>&1 </dev/null ||
            result=killed
    fi
    failed=$(sed -n 's/^\[  FAILED  \] \([A-Za-z][A-Za-z0-9_/.]*\).*/\1/p; s/^FAIL \([^:]*\):.*/\1/p' "$log" |
        sort -u | tr '\n' ' ')
    t1=$(date +%s)
    echo "MUTANT $name: $result in $((t1 - t0)) s ${failed:+(failed: $failed)}"
    printf '| %s | %s | %s | %s | %s |\n' "$what" "$file" "$result" "$failed" "$((t1 - t0))" >>"$REPORT"
    [ "$result" = survived ] && survived=$((survived + 1))
    cp "$ROOT/$file" "$file"
}

# Entries of test/mutants.txt: blocks of "key: value" lines (name, what,
# file, from, to, first, env: variables for the run of `first`, such as the
# device), separated by blank lines; # starts a comment.
wanted() {
    [ $# -eq 0 ] && return 0
    for w in "$@"; do [ "$w" = "$name" ] && return 0; done
    return 1
}
flush() {
    if [ -n "$name" ] && wanted $selected; then
        if [ -n "$CHECK" ]; then
            if [ "$name" != "${MUTANT_APPLIED-}" ]; then
                total=$((total + 1))
                applies "$name" "$file" "$from" || broken=$((broken + 1))
            fi
        else
            run_one "$name" "$file" "$from" "$to" "${first:-*}" "${what:-$name}" "$menv"
        fi
    fi
    name= file= from= to= first= what= menv=
}
selected="$*"
name= file= from= to= first= what= menv=
while IFS= read -r line || [ -n "$line" ]; do
    case $line in
    '#'*) continue ;;
    '') flush ;;
    name:*) name=${line#name: } ;;
    what:*) what=${line#what: } ;;
    file:*) file=${line#file: } ;;
    from:*) from=${line#from: } ;;
    to:*) to=${line#to: } ;;
    first:*) first=${line#first: } ;;
    env:*) menv=${line#env: } ;;
    esac
done <"$LIST"
flush

if [ -n "$CHECK" ]; then
    echo "mutants: $total entries, $broken do not apply"
    [ "$broken" -gt 0 ] && exit 2
    exit 0
fi
end_all=$(date +%s)
echo "mutants: $total bugs, $((total - survived - broken)) killed, $survived survived, $broken broken, $((end_all - start_all)) s"
echo "report: build/mutants/report.md"
[ "$broken" -gt 0 ] && exit 2
[ "$survived" -gt 0 ] && exit 1
exit 0
