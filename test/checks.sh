# Helpers for the shell tests (sourced): each check prints "ok   NAME" or
# "FAIL NAME: why"; `summary NAME` prints "NAME: N passed, N failed", the
# line test/run_all.sh counts, and sets the exit status.
pass=0
fail=0

# check NAME EXPECTED_EXIT EXPECTED_TEXT -- COMMAND...
# An empty EXPECTED_TEXT means the command must print nothing at all.
check() {
    name=$1 want_rc=$2 want_text=$3
    shift 4
    out=$("$@" 2>&1)
    rc=$?
    if [ -z "$want_text" ]; then text_ok=$([ -z "$out" ] && echo 1); else
        text_ok=$(printf '%s' "$out" | grep -qF -- "$want_text" && echo 1); fi
    if [ "$rc" -eq "$want_rc" ] && [ -n "$text_ok" ]; then
        pass=$((pass + 1))
        echo "ok   $name"
    else
        fail=$((fail + 1))
        echo "FAIL $name: exit $rc (want $want_rc), output:"
        printf '%s\n' "$out" | sed 's/^/     /'
    fi
}

# absent NAME FILE: the file must not exist
absent() {
    if [ -e "$2" ]; then
        fail=$((fail + 1))
        echo "FAIL $1: $2 exists"
    else
        pass=$((pass + 1))
        echo "ok   $1"
    fi
}

# truth NAME COMMAND...: the command must succeed (a test written in shell)
truth() {
    name=$1
    shift
    if "$@"; then
        pass=$((pass + 1))
        echo "ok   $name"
    else
        fail=$((fail + 1))
        echo "FAIL $name"
    fi
}

# no_temporaries DIR: no half-written file (.tmp-*) may be left in DIR
no_temporaries() {
    leftover=$(ls -A "$1" | grep '^\.tmp-' || true)
    if [ -z "$leftover" ]; then pass=$((pass + 1)); echo "ok   no temporary files in $1"; else
        fail=$((fail + 1)); echo "FAIL temporary files left: $leftover"; fi
}

summary() {
    echo "$1: $pass passed, $fail failed"
    [ "$fail" -eq 0 ]
}
