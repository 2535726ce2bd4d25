# Summary of bench/ab_mutations.sh's runs.csv "scene,binary,run,
# mutations_per_s,atomics_per_mutation": per scene the medians of A and B,
# their ratio B/A and each one's atomics per mutation.
NR > 1 { k = $1 SUBSEP $2; n = ++cnt[k]; v[k, n] = $4; at[k] = $5; if (!($1 in seen)) { seen[$1] = 1; sc[++ns] = $1 } }
END { print "scene,A_mutations_per_s,B_mutations_per_s,ratio_B_over_A,A_atomics_per_mutation,B_atomics_per_mutation"
    for (i = 1; i <= ns; ++i) { for (b = 0; b < 2; ++b) { k = sc[i] SUBSEP (b ? "B" : "A"); for (j = 1; j <= cnt[k]; ++j) x[j] = v[k, j]; m[b] = median(x, cnt[k]) }
        printf "%s,%.4g,%.4g,%.3f,%s,%s\n", sc[i], m[0], m[1], m[1] / m[0], at[sc[i] SUBSEP "A"], at[sc[i] SUBSEP "B"] } }
