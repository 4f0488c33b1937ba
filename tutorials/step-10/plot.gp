# The figure of step-10 (README.md), from output/wall.csv, which the
# program writes: one row per node of the wall on the scene's last mesh
# (y, l1_p1, l1_q1, l2_p1, l2_q1, status_p1, status_q1).
# Run from this folder after the program: gnuplot plot.gp
#   pressure.svg  the contact pressure l1 along the wall, P1 on triangles
#                 and Q1 on quadrilaterals with the same nodes; the inset
#                 shows the top of the wall, where the stress is singular
set datafile separator ','
set terminal svg size 720,480 dynamic font 'Helvetica,14'
set output 'pressure.svg'
file = 'output/wall.csv'

set multiplot
set title 'The block against the wall: the pressure on the last mesh'
set xlabel 'height y on the wall'
set ylabel 'contact pressure l_1'
set xrange [0:1]
set yrange [20:80]
set grid
set key at graph 0.03, graph 0.95 left top box opaque
plot file using 1:2 skip 1 with linespoints pt 7 ps 0.5 lw 2 \
       lc rgb '#d62728' title 'P1, triangles', \
     file using 1:3 skip 1 with linespoints pt 6 ps 0.7 lw 2 dt 2 \
       lc rgb '#1f77b4' title 'Q1, quadrilaterals'

# the inset: the top tenth of the wall
set origin 0.47, 0.40
set size 0.40, 0.46
unset title
set xlabel 'y' offset 0, 0.5
set ylabel ''
set xrange [0.9:1]
set yrange [30:75]
set xtics 0.05
set ytics 10
set object 1 rectangle from graph 0, graph 0 to graph 1, graph 1 \
  behind fc rgb 'white' fillstyle solid 1.0
unset key
plot file using 1:2 skip 1 with linespoints pt 7 ps 0.5 lw 2 \
       lc rgb '#d62728', \
     file using 1:3 skip 1 with linespoints pt 6 ps 0.7 lw 2 dt 2 \
       lc rgb '#1f77b4'
unset multiplot
