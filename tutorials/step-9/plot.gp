# The figure of step-9 (README.md), from output/degrees.csv, which the
# program writes: one row per mesh of every run (nu, degree, cycle, cells,
# dofs, contact_nodes, pressure_error, peak_error, half_width_error,
# cg_per_newton).
# Run from this folder after the program: gnuplot plot.gp
#   pressure_error.svg  the relative L2 error of the contact pressure
#                       against the DoFs, degrees 1, 2, 3 at nu = 0.3 (lines)
#                       and degrees 1, 2 at nu = 0.49 (open points), with
#                       the slope N^(-1/2) of an error of order h
set datafile separator ','
set terminal svg size 720,480 dynamic font 'Helvetica,14'
set output 'pressure_error.svg'
set title 'Hertz cylinder, global refinement: the pressure error by degree'
set xlabel 'DoFs N'
set ylabel 'relative L2 error of the pressure on {/Symbol G}_C'
set logscale xy
set format y '10^{%L}'
set grid
set key top right

file = 'output/degrees.csv'
colour(k) = k == 1 ? '#1f77b4' : (k == 2 ? '#2ca02c' : '#d62728')
at(nu, k, y) = abs($1 - nu) < 1e-9 && $2 == k ? y : 1/0
# the slope -1/2 through degree 1's first mesh (fewest DoFs, largest error)
stats file using (at(0.3, 1, $5)):(at(0.3, 1, $7)) every ::1 nooutput
N0 = STATS_min_x
e0 = STATS_max_y

plot for [k = 1:3] file using (at(0.3, k, $5)):(at(0.3, k, $7)) every ::1 \
       with linespoints pt 7 ps 0.8 lw 2 lc rgb colour(k) \
       title sprintf('degree %d, {/Symbol n} = 0.3', k), \
     for [k = 1:2] file using (at(0.49, k, $5)):(at(0.49, k, $7)) every ::1 \
       with points pt 6 ps 1.2 lw 2 lc rgb colour(k) \
       title sprintf('degree %d, {/Symbol n} = 0.49', k), \
     e0 * (x / N0)**(-0.5) with lines dt 2 lc rgb 'black' title 'N^{-1/2}'
