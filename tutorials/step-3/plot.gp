# The figures of step-3 (README.md), from the CSV files the program writes
# into output/. Run from this folder: gnuplot plot.gp
set datafile separator ','
set terminal svg size 720,460 dynamic font 'sans,13'
set grid

# The multipliers along the wall (the merged solution on the finest
# mesh). Slip where |l2| = F l1.
set output 'stick_slip.svg'
set title 'The block against the wall (F = 0.3), finest mesh'
set xlabel 'position along the wall y'
set ylabel 'traction'
set xrange [0:1]
set yrange [0:22]
set key at graph 0.03, graph 0.62 left top box opaque
plot 'output/contact.csv' using 1:2 skip 1 with lines lw 2 lc rgb '#1f77b4' title 'pressure l1', \
     ''                   using 1:6 skip 1 with lines lw 2 dt 2 lc rgb '#d62728' title 'threshold θ = F l1', \
     ''                   using 1:4 skip 1 with lines lw 2 lc rgb '#2ca02c' title 'tangential traction |l2|', \
     ''                   using 1:($7 == 2 ? $4 : 1/0) skip 1 with points pt 7 ps 0.6 lc rgb '#2ca02c' title 'slip nodes'

# The threshold iteration's convergence against the Uzawa steps it
# costs, on the first mesh (cold start).
set output 'threshold_history.svg'
set title 'The threshold iteration on the first mesh'
set xlabel 'Uzawa steps so far'
set ylabel 'd(θ) = |θ_{new} - θ| / |θ_{new}|'
set logscale y
set format y '10^{%L}'
set xrange [0:*]
set yrange [1e-10:1e4]
set key default
set key top right box opaque
plot 'output/threshold_history.csv' using 2:(strcol(1) eq 'nested' ? $3 : 1/0) skip 1 with linespoints lw 2 pt 7 lc rgb '#ff7f0e' title 'nested: after each given-threshold solve', \
     ''                             using 2:(strcol(1) eq 'merged' ? $3 : 1/0) skip 1 with linespoints lw 2 pt 5 lc rgb '#1f77b4' title 'merged: after each Uzawa step', \
     1e-6 with lines dt 2 lc rgb '#7f7f7f' title 'threshold tolerance'
unset logscale y
set format y '%g'
