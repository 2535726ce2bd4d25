#!/bin/sh
# The source layout of doc/design.md: each folder of src/ includes only from
# the folders below it, and no two files include each other; each folder of
# cl/ (a stage of the kernels) calls only functions of its own folder and of
# the folders below it, and the product's binary holds no test kernel.
# Usage: layout_test.sh [SMALLMLT_BIN] (run from the repository root)
BIN=${1:-build/smallmlt}
. test/checks.sh

# allowed FOLDER: the folders FOLDER may include from (besides itself).
allowed() {
    case $1 in
    base) echo "" ;;
    image) echo "base" ;;
    scene) echo "base" ;;
    device) echo "base scene" ;;
    render) echo "base image scene device" ;;
    app) echo "base image scene device render" ;;
    mpi) echo "base image scene device render app" ;;
    *) echo "UNKNOWN" ;;
    esac
}

folders_known() {
    for d in src/*/; do
        d=$(basename "$d")
        [ "$(allowed "$d")" = UNKNOWN ] && { echo "src/$d is not in the layout"; return 1; }
    done
    return 0
}
truth every_folder_has_a_stage folders_known

arrows_point_down() {
    ok=0
    for f in src/*/*.cpp src/*/*.hpp; do
        d=$(basename "$(dirname "$f")")
        for t in $(sed -n 's|^#include "\([a-z_]*\)/.*|\1|p' "$f" | sort -u); do
            [ "$t" = "$d" ] && continue
            case " $(allowed "$d") " in
            *" $t "*) ;;
            *) echo "$f includes from $t/"; ok=1 ;;
            esac
        done
    done
    return $ok
}
truth arrows_point_down arrows_point_down

# Every include of smallmlt's own headers names its folder.
includes_qualified() {
    bad=$(grep -n '^#include "[a-z_]*\.hpp"' src/*/*.cpp src/*/*.hpp)
    [ -z "$bad" ] || { echo "$bad"; return 1; }
}
truth includes_name_their_folder includes_qualified

# No header includes a header that includes it back (nor a .cpp the other's
# header both ways).
no_mutual_includes() {
    ok=0
    for f in src/*/*.hpp src/*/*.cpp; do
        a=${f#src/}
        a=${a%.*}
        for t in $(sed -n 's|^#include "\([a-z_]*/[a-z_]*\)\.hpp"|\1|p' "$f"); do
            [ "$t" = "$a" ] && continue
            for g in "src/$t.hpp" "src/$t.cpp"; do
                [ -f "$g" ] || continue
                if grep -q "^#include \"$a\.hpp\"" "$g"; then
                    echo "$f and $g include each other"
                    ok=1
                fi
            done
        done
    done
    return $ok
}
truth no_two_files_depend_on_each_other no_mutual_includes

# The stages of cl/, bottom up (src/render/programs.hpp builds in this
# order): cl_rank FOLDER prints its place.
cl_rank() {
    case $1 in
    core) echo 0 ;; geometry) echo 1 ;; sampling) echo 2 ;; shading) echo 3 ;;
    path) echo 4 ;; mlt) echo 5 ;; kernels) echo 6 ;; *) echo UNKNOWN ;;
    esac
}

cl_folders_known() {
    for d in cl/*/; do
        d=$(basename "$d")
        [ "$(cl_rank "$d")" = UNKNOWN ] && { echo "cl/$d is not a stage"; return 1; }
    done
    [ -z "$(ls cl/*.cl cl/*.h 2>/dev/null)" ] || { echo "files outside a stage of cl/"; return 1; }
}
truth every_kernel_folder_is_a_stage cl_folders_known

# cl_defs FILE: the functions and function-like macros FILE defines (at
# the start of a line: a definition, not a call).
cl_defs() {
    sed -n -E -e 's/^[A-Za-z_][^=;(#]*[ *]([a-z_][a-z0-9_]*)\(.*/\1/p' \
        -e 's/^#define ([a-z_][a-z0-9_]*)\(.*/\1/p' "$1" | sort -u
}

cl_calls_point_down() {
    defs=$(mktemp)
    for f in cl/*/*.cl cl/*/*.h; do
        for fn in $(cl_defs "$f"); do echo "$fn $(basename "$(dirname "$f")")"; done
    done | sort -u > "$defs"
    ok=0
    for f in cl/*/*.cl cl/*/*.h; do
        d=$(basename "$(dirname "$f")")
        r=$(cl_rank "$d")
        for fn in $(sed -e 's|/\*.*\*/||g' -e 's|^ *\*.*||' "$f" |
            grep -oE '\b[a-z_][a-z0-9_]*\(' | tr -d '(' | sort -u); do
            for t in $(awk -v fn="$fn" '$1 == fn { print $2 }' "$defs"); do
                if [ "$(cl_rank "$t")" -gt "$r" ]; then
                    echo "$f calls $fn of cl/$t/"
                    ok=1
                fi
            done
        done
    done
    rm -f "$defs"
    return $ok
}
truth kernel_calls_point_down cl_calls_point_down

# The test kernels (test/cl/) are embedded into the test binary alone.
no_test_kernel_in_product() {
    bin=${1:-build/smallmlt}
    [ -f "$bin" ] || { echo "no $bin to look into"; return 1; }
    for f in test/cl/*.cl; do
        for k in $(sed -n -E 's/^__kernel void ([a-z_0-9]*)\(.*/\1/p' "$f"); do
            if strings "$bin" | grep -qw "$k"; then echo "$bin holds $k of $f"; return 1; fi
        done
    done
}
truth product_has_no_test_kernel no_test_kernel_in_product "$BIN"

summary layout
