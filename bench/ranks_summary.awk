# Summary of bench/ranks.sh's runs.csv "config,run,what,value": per
# configuration the median of each figure.
NR > 1 { k = $1 SUBSEP $3; n = ++cnt[k]; v[k, n] = $4
    if (!($1 in sc)) { sc[$1] = 1; cs[++nc] = $1 } if (!($3 in sw)) { sw[$3] = 1; ws[++nw] = $3 } }
END { printf "config"; for (j = 1; j <= nw; ++j) printf ",%s", ws[j]; print ""
    for (i = 1; i <= nc; ++i) { printf "%s", cs[i]
        for (j = 1; j <= nw; ++j) { k = cs[i] SUBSEP ws[j]; for (r = 1; r <= cnt[k]; ++r) x[r] = v[k, r]; printf ",%.4g", median(x, cnt[k]) }
        print "" } }
