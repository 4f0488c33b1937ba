# The figure of step-2 (run from tutorials/step-2 after the program):
#   newton.svg  |G|/f_ref per Newton iterate of proximal step 1 (from v = 0,
#               l1 = 0), by hand and by the library's NewtonSolver, and the
#               active nodes at each iterate
set datafile separator ','
set terminal svg size 720,480 dynamic font 'Helvetica,14'

set output 'newton.svg'
set title 'Proximal step 1: semi-smooth Newton by hand and by the library'
set xlabel 'Newton iterate j'
set ylabel '|G(v_j)| / f_{ref}'
set logscale y
set format y '10^{%L}'
set yrange [1e-12:1e3]
set y2label 'active nodes (z_s >= 0)'
set y2range [0:80]
set y2tics 0, 10, 80
set ytics nomirror
set xrange [-0.5:8.5]
set key bottom left
set grid
tolerance = 1e-10
plot 'output/newton.csv' using 2:($1 == 1 ? $4 : 1/0) every ::1 \
       with lines lw 2 lc rgb '#1f77b4' title 'library (NewtonSolver)', \
     '' using 2:($1 == 1 ? $3 : 1/0) every ::1 \
       with points pt 7 ps 0.9 lc rgb '#d62728' title 'by hand', \
     '' using 2:($1 == 1 ? $5 : 1/0) every ::1 axes x1y2 \
       with linespoints dt 2 pt 4 lc rgb '#555555' title 'active nodes', \
     tolerance with lines dt 3 lc rgb '#2ca02c' title 'tolerance'
