#!/bin/sh
# Every path of the repository that a comment or a doc names exists: in the
# comments of src/, cl/, test/, bench/ and scenes/generate.py, and anywhere
# in the Makefile, README.md and doc/*.md. A path is a word that starts with
# a folder of the repository (src, cl, test, doc, bench, scenes or tools,
# then a slash) and ends in an extension or a slash, or a top-level file
# such as README.md; in Markdown, a link's target too, from its file's
# folder. A glob (cl/*/*.cl, or a Makefile pattern, whose % spans folders)
# must match some file. Not checked: placeholders (cl/<stage>/<file>), the
# build outputs that .gitignore names (bench/results/...; build/ is no
# folder of the sources), and a path after "github.com/OWNER/REPO, ", which
# is that repository's (doc/devices.md).
# Usage: paths_test.sh [SMALLMLT_BIN] (run from the repository root; the
# binary is not used)
. test/checks.sh

# comments FILE...: "FILE:LINE:TEXT" for the comments of each source file
# (// and /* */ outside strings, # in shell, awk and Python, and Python's
# docstrings) and for every line of a Markdown file and of the Makefile.
comments() {
    c='' text='' txt='' hash=''
    for f in "$@"; do
        case $f in
        *.cpp | *.hpp | *.cl | *.h) c="$c $f" ;;
        *.md | Makefile) text="$text $f" ;;
        *.txt) txt="$txt $f" ;;
        *) hash="$hash $f" ;;
        esac
    done
    # shellcheck disable=SC2086 # lists of paths without spaces
    {
        [ -z "$c" ] || c_comments $c
        [ -z "$text" ] || awk '{ print FILENAME ":" FNR ":" $0 }' $text
        # test/mutants.txt: as test/mutants.sh reads it, only whole lines.
        [ -z "$txt" ] || awk '/^#/ { print FILENAME ":" FNR ":" $0 }' $txt
        [ -z "$hash" ] || hash_comments $hash
    }
}

# c_comments FILE...
c_comments() {
    awk '
    function flush() { if (buf != "") print FILENAME ":" FNR ":" buf; buf = "" }
    FNR == 1 { st = "code" }
    {
        if (st == "str") st = "code"
        n = length($0)
        for (i = 1; i <= n; ) {
            c = substr($0, i, 1); c2 = substr($0, i, 2)
            if (st == "block") {
                if (c2 == "*/") { st = "code"; i += 2 } else { buf = buf c; i++ }
            } else if (st == "raw") {
                p = index(substr($0, i), rawend)
                if (p == 0) i = n + 1; else { i += p - 1 + length(rawend); st = "code" }
            } else if (st == "str") {
                if (c == "\\") i += 2; else { if (c == q) st = "code"; i++ }
            } else if (c2 == "//") {
                buf = buf substr($0, i + 2); i = n + 1
            } else if (c2 == "/*") {
                st = "block"; buf = buf " "; i += 2
            } else if (c2 == "R\"" && substr($0, i + 2) ~ /^[A-Za-z_]*\(/) {
                d = substr($0, i + 2); d = substr(d, 1, index(d, "(") - 1)
                rawend = ")" d "\""; st = "raw"; i += length(d) + 3
            } else if (c == "\"" || c == "'\''") {
                q = c; st = "str"; i++
            } else i++
        }
        flush()
    }' "$@"
}

# hash_comments FILE...: the text after a # that starts a word outside quotes;
# in Python also the lines of a docstring.
hash_comments() {
    awk '
    FNR == 1 { py = FILENAME ~ /\.py$/; doc = 0 }
    {
        if (py && doc) { print FILENAME ":" FNR ":" $0; if (index($0, "\"\"\"")) doc = 0; next }
        if (py && index($0, "\"\"\"")) {
            print FILENAME ":" FNR ":" $0
            rest = substr($0, index($0, "\"\"\"") + 3)
            if (!index(rest, "\"\"\"")) doc = 1
            next
        }
        q = ""
        n = length($0)
        for (i = 1; i <= n; i++) {
            c = substr($0, i, 1)
            if (q != "") { if (c == q) q = ""; continue }
            if (c == "\"" || c == "'\''") { q = c; continue }
            if (c == "#" && (i == 1 || substr($0, i - 1, 1) ~ /[ \t]/)) {
                print FILENAME ":" FNR ":" substr($0, i + 1)
                break
            }
        }
    }' "$@"
}

# named_paths: reads "FILE:LINE:TEXT", prints "FILE:LINE:PATH" for each path
# the text names (a Markdown link's target joined to its file's folder).
named_paths() {
    awk '
    BEGIN {
        pre = "(^|[^A-Za-z0-9_./-])"
        word = pre "((src|cl|test|doc|bench|scenes|tools)/[A-Za-z0-9_.*<>%/-]*|[A-Z][A-Za-z0-9_-]*\\.md)"
    }
    {
        file = $0; sub(/:.*/, "", file)
        line = substr($0, length(file) + 2); sub(/:.*/, "", line)
        text = substr($0, length(file) + length(line) + 3)
        dir = file; if (!sub(/\/[^\/]*$/, "/", dir)) dir = ""
        t = text
        while (match(t, word)) {
            s = RSTART; l = RLENGTH
            if (substr(t, s, 1) !~ /[A-Za-z]/) { s++; l-- }
            p = substr(t, s, l); before = substr(t, 1, s - 1); t = substr(t, s + l)
            sub(/[.,:;-]+$/, "", p)
            if (p !~ /(\.[A-Za-z0-9]+|\/|\*)$/) continue
            if (before ~ /github\.com\/[A-Za-z0-9_.-]+\/[A-Za-z0-9_.-]+, *$/) continue
            if (p ~ /^[A-Z][^\/]*$/ && dir != "") print file ":" line ":" p "|" dir p
            else print file ":" line ":" p
        }
        if (file !~ /\.md$/) next
        t = text
        while (match(t, /\]\([^)# ]+/)) {
            p = substr(t, RSTART + 2, RLENGTH - 2); t = substr(t, RSTART + RLENGTH)
            if (p ~ /^[a-z]+:/) continue
            print file ":" line ":" dir p
        }
    }'
}

# stale_paths FILE...: "FILE:LINE: PATH does not exist" for each path named
# in the files that is not in the tree.
stale_paths() {
    ignored=$(sed -n 's|^/\{0,1\}\([^#!*]*/\)$|\1|p' .gitignore 2>/dev/null)
    comments "$@" | named_paths | while IFS= read -r entry; do
        at=${entry%:*} p=${entry##*:}
        case $p in *'<'* | *'>'*) continue ;; esac
        skip=
        for g in $ignored; do case $p in "$g"*) skip=1 ;; esac; done
        [ -n "$skip" ] && continue
        found=
        # PATH|ALTERNATIVE: a top-level name, or one beside its doc.
        for q in "${p%%|*}" "${p#*|}"; do
            case $q in
            *%*) [ -n "$(find . -path "./$(echo "$q" | tr % '*')" | head -n 1)" ] && found=1 ;;
            *)
                # shellcheck disable=SC2086 # the glob is meant to expand
                set -- $q
                [ -e "$1" ] && found=1
                ;;
            esac
        done
        [ -n "$found" ] || echo "$at: ${p%%|*} does not exist"
    done | awk '!seen[$0]++'
}

sources() {
    find src cl test bench -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.cl' \
        -o -name '*.h' -o -name '*.sh' -o -name '*.awk' -o -name '*.txt' -o -name '*.supp' \) |
        sort
    echo scenes/generate.py Makefile README.md doc/*.md | tr ' ' '\n'
}

every_named_path_exists() {
    # shellcheck disable=SC2046 # no path of the tree holds a space
    stale=$(stale_paths $(sources))
    [ -z "$stale" ] || { echo "$stale"; return 1; }
}
truth every_named_path_exists every_named_path_exists

# The check itself, on a tree of its own: what it must find and what not.
finds_what_it_should() {
    dir=$(mktemp -d)
    (
        cd "$dir" || exit 1
        mkdir -p src/a cl/core doc/img bench
        printf '/bench/results/\n/build/\n' > .gitignore
        touch cl/core/rng.cl doc/img/x.png doc/RESULTS.md
        cat > src/a/f.cpp <<'EOF'
// cl/core/rng.cl exists, src/a/gone.cpp does not
int x; /* cl/core/old.cl, and cl/*/*.cl matches */ const char* s = "cl/nope.cl // src/no.cpp";
/* cl/<stage>/<file>, bench/results/a.csv, build/gen/k.cpp, scenes/furnace
 */ // and cl/*/*.h matches nothing
const char* r = R"x(src/raw.cpp)x"; // README.md
EOF
        printf '# src/%%/f.cpp, test/%%.cpp\nA = src/%%.cpp src/b/\n' > Makefile
        printf 'See [x](img/x.png), [y](img/y.png), RESULTS.md, doc/RESULTS.md,\n' > doc/a.md
        printf 'github.com/o/r, doc/source/other.rst, https://o.org/src/x.cpp.\n' >> doc/a.md
        stale_paths src/a/f.cpp Makefile doc/a.md
    ) > "$dir.out" 2>&1
    want='src/a/f.cpp:1: src/a/gone.cpp does not exist
src/a/f.cpp:2: cl/core/old.cl does not exist
src/a/f.cpp:4: cl/*/*.h does not exist
src/a/f.cpp:5: README.md does not exist
Makefile:1: test/%.cpp does not exist
Makefile:2: src/b/ does not exist
doc/a.md:1: doc/img/y.png does not exist'
    ok=0
    [ "$(cat "$dir.out")" = "$want" ] || { echo "found:"; cat "$dir.out"; echo "want:"; echo "$want"; ok=1; }
    rm -rf "$dir" "$dir.out"
    return $ok
}
truth finds_stale_paths_and_no_others finds_what_it_should

summary paths
