# Time each method needs to reach a target error, from a convergence-log CSV
# "method,seed,seconds,samples_per_pixel,samples,mse,rel_mse" (rows of one
# render in time order). The target is the largest of PT's final MSEs over
# the seeds: the error every PT render reached by its end.
# A render reaches it at its first row at or below it, interpolated in
# log-log against the row before; one that never does is extrapolated from
# its last row as MSE ~ 1/t (the Monte Carlo rate) and marked. Prints
# "scene,method,ratio_to_pt,seconds,pt_seconds,target_mse,reached" with
# medians over seeds. Usage: awk -F, -v scene=NAME -f median.awk -f time_to_error.awk CSV
NR == 1 { next }
{
    key = $1 SUBSEP $2
    if (!(key in rows)) { order[++nkeys] = key; if (!($1 in seen)) { seen[$1] = 1; methods[++nm] = $1 } }
    n = ++rows[key]
    t[key, n] = $3; e[key, n] = $6
}
END {
    np = 0
    for (k = 1; k <= nkeys; ++k) {
        split(order[k], f, SUBSEP)
        if (f[1] == "pt") pt_final[++np] = e[order[k], rows[order[k]]]
    }
    if (np == 0) { print "time_to_error: no pt rows" > "/dev/stderr"; exit 1 }
    target = pt_final[1]
    for (j = 2; j <= np; ++j) if (pt_final[j] > target) target = pt_final[j]
    for (k = 1; k <= nkeys; ++k) {
        key = order[k]; split(key, f, SUBSEP); m = f[1]
        reach = -1
        for (i = 1; i <= rows[key] && reach < 0; ++i) {
            if (e[key, i] > target) continue
            if (i == 1 || e[key, i] == e[key, i - 1]) { reach = t[key, i]; continue }
            a = log(e[key, i - 1] / target) / log(e[key, i - 1] / e[key, i])
            reach = exp(log(t[key, i - 1]) + a * (log(t[key, i]) - log(t[key, i - 1])))
        }
        if (reach < 0) {
            last = rows[key]
            reach = t[key, last] * e[key, last] / target
            extrapolated[m] = 1
        }
        times[m, ++count[m]] = reach
    }
    for (j = 1; j <= count["pt"]; ++j) v[j] = times["pt", j]
    pt_time = median(v, count["pt"])
    for (i = 1; i <= nm; ++i) {
        m = methods[i]
        for (j = 1; j <= count[m]; ++j) v[j] = times[m, j]
        mt = median(v, count[m])
        printf "%s,%s,%.3f%s,%.2f,%.2f,%.6g,%s\n", scene, m, mt / pt_time, m in extrapolated ? "*" : "",
            mt, pt_time, target, m in extrapolated ? "no" : "yes"
    }
}
