# Figures of step-5 from the cycles.csv of its runs (output/<run>/).
# Run from this folder after the program: gnuplot plot.gp
#   work_precision.svg  pressure error against cumulative wall time
#   error_vs_dofs.svg   pressure error against the number of DoFs
set terminal svg size 720,520 dynamic noenhanced font "sans,13"
set datafile separator ","
set logscale xy
set format y "%g"
set grid
set key top right box opaque
set ylabel "relative L2 error of the contact pressure on Γ_C"

strategies = "global kelly contact edge"
colour(i) = word("#1f77b4 #ff7f0e #2ca02c #d62728", i)
file(s, start) = sprintf("output/%s-%s/cycles.csv", s, start)

# the coarse mesh (cycle 0 of any run) anchors the reference slopes
stats file("global", "nested") using "dofs" every ::0::0 nooutput
N0 = STATS_min
stats file("global", "nested") using "pressure_error" every ::0::0 nooutput
e0 = STATS_min

set output "work_precision.svg"
set title "What accuracy costs: error against the wall time of all cycles so far"
set xlabel "cumulative wall time (time_total) [s]"
set format x "%g"
plot for [i=1:4] file(word(strategies, i), "nested") \
       using "time_total":"pressure_error" with linespoints \
       lw 2 pt 7 lc rgb colour(i) dt 1 title word(strategies, i)." nested", \
     for [i=1:3] file(word(strategies, i), "cold") \
       using "time_total":"pressure_error" with linespoints \
       lw 2 pt 6 lc rgb colour(i) dt 2 title word(strategies, i)." cold"

set output "error_vs_dofs.svg"
set title "Error against degrees of freedom (nested and cold runs coincide)"
set xlabel "degrees of freedom N"
set format x "%g"
plot for [i=1:4] file(word(strategies, i), "nested") \
       using "dofs":"pressure_error" with linespoints \
       lw 2 pt 7 lc rgb colour(i) title word(strategies, i), \
     e0 * (x / N0)**(-0.5) with lines lc rgb "gray" dt 3 lw 1.5 \
       title "N^(-1/2), O(h)", \
     e0 * (x / N0)**(-1) with lines lc rgb "black" dt 3 lw 1.5 \
       title "N^(-1)"
