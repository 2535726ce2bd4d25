#!/bin/sh
# MLT throughput of two binaries side by side: renders each scene with A and
# B in turn (A B A B ...), RUNS times each, and prints the median mutations/s
# of the steps (the render summary's figure, which leaves out burn-in and
# set-up) of each, their ratio B/A, and each binary's global atomics per
# mutation where its summary gives them. Usage: bench/ab_mutations.sh BIN_A BIN_B
# Settings (environment): SCENES, SIZE, SPP, THREADS, RUNS; FLAGS_A and
# FLAGS_B are added to A's and B's command lines, so that one binary can be
# run both ways (FLAGS_A="--film-atomics 64": the 64-bit film against the
# 32-bit one).
set -eu
A=$1 B=$2
SCENES=${SCENES:-cornell cornell-water}
SIZE=${SIZE:-128}
SPP=${SPP:-64}
THREADS=${THREADS:-65536}
RUNS=${RUNS:-5}
FLAGS_A=${FLAGS_A:-}
FLAGS_B=${FLAGS_B:-}
OUT=${RESULTS:-bench/results}/ab_mutations
mkdir -p "$OUT"
echo "scene,binary,run,mutations_per_s,atomics_per_mutation" > "$OUT/runs.csv"
for scene in $SCENES; do
    r=1
    while [ "$r" -le "$RUNS" ]; do
        for bin in A B; do
            if [ "$bin" = A ]; then exe=$A flags=$FLAGS_A; else exe=$B flags=$FLAGS_B; fi
            # shellcheck disable=SC2086 # the flags are words
            "$exe" render "scenes/$scene.scene" --method mlt --threads "$THREADS" --spp "$SPP" $flags \
                --width "$SIZE" --height "$SIZE" --seed "$r" --out "$OUT/last.pfm" |
                awk -v s="$scene" -v b="$bin" -v r="$r" '/ mlt: / {
                    m = $0; sub(/ M mutations\/s.*/, "", m); sub(/.*, /, "", m)
                    a = "NA"; if ($0 ~ /global atomics/) { a = $0; sub(/ global atomics.*/, "", a); sub(/.*, /, "", a) }
                    print s "," b "," r "," m * 1e6 "," a }' >> "$OUT/runs.csv"
        done
        r=$((r + 1))
    done
done
rm -f "$OUT/last.pfm"
awk -F, 'function median(a, n,    i, j, t) {
        for (i = 2; i <= n; ++i) for (j = i; j > 1 && a[j - 1] > a[j]; --j) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
        return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
    NR > 1 { k = $1 SUBSEP $2; n = ++cnt[k]; v[k, n] = $4; at[k] = $5; if (!($1 in seen)) { seen[$1] = 1; sc[++ns] = $1 } }
    END { print "scene,A_mutations_per_s,B_mutations_per_s,ratio_B_over_A,A_atomics_per_mutation,B_atomics_per_mutation"
        for (i = 1; i <= ns; ++i) { for (b = 0; b < 2; ++b) { k = sc[i] SUBSEP (b ? "B" : "A"); for (j = 1; j <= cnt[k]; ++j) x[j] = v[k, j]; m[b] = median(x, cnt[k]) }
            printf "%s,%.4g,%.4g,%.3f,%s,%s\n", sc[i], m[0], m[1], m[1] / m[0], at[sc[i] SUBSEP "A"], at[sc[i] SUBSEP "B"] } }' \
    "$OUT/runs.csv" | tee "$OUT/summary.csv"
