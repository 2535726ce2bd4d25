#!/bin/sh
# Log-log chart of error against wall time from a CSV whose rows are
# "series,seconds,mse,...": one line per series (those in the CSV).
# Usage: bench/plot_error.sh CSV OUT.png TITLE SERIES=LABEL...
set -eu
csv=$1 out=$2 title=$3
shift 3
{
    echo "set terminal pngcairo size 640,420 font ',10'"
    echo "set output '$out'"
    echo "set datafile separator ','"
    echo "set logscale xy; set grid; set key bottom left"
    echo "set xlabel 'wall time (s)'; set ylabel 'MSE against PT reference'"
    echo "set title '$title'"
    printf "plot "
    sep=""
    for pair in "$@"; do
        grep -q "^${pair%%=*}," "$csv" || continue # a series this run left out
        printf "%s'< grep ^%s, %s' using 2:3 with linespoints title '%s'" "$sep" "${pair%%=*}" "$csv" "${pair#*=}"
        sep=", "
    done
    echo
} | gnuplot
