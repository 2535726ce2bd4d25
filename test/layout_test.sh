#!/bin/sh
# The source layout of doc/design.md: each folder of src/ includes only from
# the folders below it, and no two files include each other.
# Usage: layout_test.sh [SMALLMLT_BIN] (unused; run from the repository root)
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

summary layout
