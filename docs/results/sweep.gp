# SPDX-License-Identifier: MIT
# Step time against N per family (docs/results.md, "Fast at the defaults"):
#   gnuplot -e "csv='sweep.csv'; out='sweep.svg'" sweep.gp
# from the CSV of tools/bench-world --sweep (all sizes in one file). One
# panel per family, one line per size: nanoseconds per object per step
# against N at the automatic depth; the defaults (N and depth both
# chosen by the world) are the filled circles, at the N they chose.
if (!exists("csv")) csv = 'sweep.csv'
if (!exists("out")) out = 'sweep.svg'
set terminal svg size 1400,720 dynamic font 'sans,11'
set output out
set datafile separator ','
set multiplot layout 2,4 title 'Step time against N per family (ns per object per step; filled circle: the defaults)'
set logscale x 2
set xrange [4:160]
set xtics (5, 10, 20, 30, 50, 80, 128)
set xlabel 'N'
set ylabel 'ns per object per step'
set key top right font 'sans,9'
families = 'planes gas mixed clusters static escape keyframes arms'
sizes = '1000 10000 100000 1000000'
sel(f, s) = (strcol(1) eq f && column(2) == s)
do for [f in families] {
    set title f
    plot for [i = 1:words(sizes)] csv skip 1 \
             using ((sel(f, word(sizes, i) + 0) && strcol(4)[1:2] eq 'N ') ? $5 : NaN):(1e9 * $9 / $3) \
             with linespoints lc i pt 6 title (f eq 'arms' ? (i == 1 ? '46 objects' : '') : word(sizes, i)), \
         for [i = 1:words(sizes)] csv skip 1 \
             using ((sel(f, word(sizes, i) + 0) && strcol(4) eq 'defaults') ? $5 : NaN):(1e9 * $9 / $3) \
             with points lc i pt 7 ps 1.6 notitle
}
unset multiplot
