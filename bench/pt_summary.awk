# Summary of bench/pt_equal_time.sh's CSV "scene,setting,seed,seconds,spp,
# mse,rel_mse": medians over seeds per (scene, setting), each setting's median
# MSE and relative MSE as a ratio of the first setting's, then per setting the
# geometric mean of those ratios over the scenes.
NR == 1 { next }
{
    if (!($1 in seen_scene)) { seen_scene[$1] = 1; scenes[++ns] = $1 }
    if (!($2 in seen_set)) { seen_set[$2] = 1; sets[++nc] = $2 }
    k = $1 SUBSEP $2; n = ++cnt[k]
    spp[k, n] = $5; mse[k, n] = $6; rel[k, n] = $7
}
END {
    print "scene,setting,median_spp,median_mse,median_rel_mse,mse_ratio,rel_mse_ratio"
    for (i = 1; i <= ns; ++i) {
        for (j = 1; j <= nc; ++j) {
            k = scenes[i] SUBSEP sets[j]; n = cnt[k]
            for (r = 1; r <= n; ++r) { a[r] = spp[k, r]; b[r] = mse[k, r]; c[r] = rel[k, r] }
            ms[j] = median(a, n); mm[j] = median(b, n); mr[j] = median(c, n)
            rm = mm[j] / mm[1]; rr = mr[j] / mr[1]
            lm[j] += log(rm); lr[j] += log(rr)
            printf "%s,%s,%d,%.4g,%.4g,%.3f,%.3f\n", scenes[i], sets[j], ms[j], mm[j], mr[j], rm, rr
        }
    }
    for (j = 1; j <= nc; ++j)
        printf "geomean,%s,,,,%.3f,%.3f\n", sets[j], exp(lm[j] / ns), exp(lr[j] / ns)
}
