# Time each method needs to reach PT's error, by each of five metrics, from a
# convergence-log CSV "method,seed,seconds,samples_per_pixel,samples,mse,
# rel_mse,mse_unlit,block8_mse,block32_mse" (rows of one render in time order; render
# --log's columns after method and seed). For each metric the target is the
# largest of PT's final values over the seeds: the error every PT render
# reached by its end. A render reaches it at its first row at or below it,
# interpolated in log-log against the row before; one that never does is
# extrapolated from its last row as error ~ 1/t (the Monte Carlo rate) and
# marked "*". Prints one row per method,
# "scene,method,mse_ratio,rel_mse_ratio,mse_unlit_ratio,block8_mse_ratio,
# block32_mse_ratio,pt_seconds,target_mse": each metric's median time over the seeds as a
# ratio of PT's median, then PT's median time and the target by MSE. A
# metric that some row leaves empty (mse_unlit without --reference-mask)
# has an empty ratio.
# Usage: awk -F, -v scene=NAME -f median.awk -f time_to_error.awk CSV
# (NAME may be several fields: bench/error_time.sh passes SCENE,WxH)
BEGIN { nmetrics = split("6 7 8 9 10", column, " ") }
NR == 1 { next }
{
    key = $1 SUBSEP $2
    if (!(key in rows)) { order[++nkeys] = key; if (!($1 in seen)) { seen[$1] = 1; methods[++nm] = $1 } }
    n = ++rows[key]
    t[key, n] = $3
    for (c = 1; c <= nmetrics; ++c) {
        e[key, n, c] = $column[c]
        if ($column[c] == "") absent[c] = 1
    }
}
# reach_time(key, c, target): when render `key` reaches `target` by metric
# c; sets extrapolated_now when it had to extrapolate.
function reach_time(key, c, target,    i, a, last) {
    extrapolated_now = 0
    for (i = 1; i <= rows[key]; ++i) {
        if (e[key, i, c] > target) continue
        if (i == 1 || e[key, i, c] == e[key, i - 1, c]) return t[key, i]
        a = log(e[key, i - 1, c] / target) / log(e[key, i - 1, c] / e[key, i, c])
        return exp(log(t[key, i - 1]) + a * (log(t[key, i]) - log(t[key, i - 1])))
    }
    extrapolated_now = 1
    last = rows[key]
    return t[key, last] * e[key, last, c] / target
}
# median_time(m, c): the median over method m's seeds of its time by metric c.
function median_time(m, c,    j, v) {
    for (j = 1; j <= count[m, c]; ++j) v[j] = times[m, c, j]
    return median(v, count[m, c])
}
END {
    for (k = 1; k <= nkeys; ++k) { split(order[k], f, SUBSEP); has_pt = has_pt || f[1] == "pt" }
    if (!has_pt) { print "time_to_error: no pt rows" > "/dev/stderr"; exit 1 }
    for (c = 1; c <= nmetrics; ++c) {
        if (c in absent) continue
        target[c] = -1
        for (k = 1; k <= nkeys; ++k) {
            split(order[k], f, SUBSEP)
            if (f[1] == "pt" && e[order[k], rows[order[k]], c] > target[c]) target[c] = e[order[k], rows[order[k]], c]
        }
        for (k = 1; k <= nkeys; ++k) {
            key = order[k]; split(key, f, SUBSEP); m = f[1]
            times[m, c, ++count[m, c]] = reach_time(key, c, target[c])
            if (extrapolated_now) extrapolated[m, c] = 1
        }
        pt_time[c] = median_time("pt", c)
    }
    for (i = 1; i <= nm; ++i) {
        m = methods[i]
        line = scene "," m
        for (c = 1; c <= nmetrics; ++c)
            line = line "," (c in absent ? "" : sprintf("%.3f%s", median_time(m, c) / pt_time[c], (m, c) in extrapolated ? "*" : ""))
        printf "%s,%.2f,%.6g\n", line, pt_time[1], target[1]
    }
}
