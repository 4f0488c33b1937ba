# Figures of step-7 from its output folder. Run from this folder after the
# program: gnuplot plot.gp
#   profile.svg  the pressure l1 and the friction traction l2_x along the x
#                axis (y = 0) against Hertz and Cattaneo-Mindlin, with F l1
#   zones.svg    the nodes in contact in the plane, stick and slip, with
#                the circles r = a (Hertz) and r = c (Cattaneo-Mindlin)
# output/exact.gp holds a, p0, c (for the measured loads) and F.
load "output/exact.gp"
set terminal svg size 720,480 dynamic noenhanced font "sans,13"
set datafile separator ","
set grid
set key box opaque

set output "profile.svg"
set title sprintf("Along y = 0: a = %.4f, c = %.4f, p0 = %.2f, F = %.2f", a, c, p0, F)
set xlabel "x / a"
set ylabel "traction / p0"
set xrange [-1.3:1.3]
set yrange [0:1.45]
set samples 801
set key top center maxrows 3 font "sans,11"
hertz(x) = abs(x) < 1 ? sqrt(1 - x * x) : 0
inner(x) = abs(x) < c / a ? (c / a) * sqrt(1 - x * x * a * a / (c * c)) : 0
cm(x) = F * (hertz(x) - inner(x))
plot hertz(x) with lines lw 2 lc rgb "#1f77b4" title "Hertz p", \
     cm(x) with lines lw 2 lc rgb "#2ca02c" title "Cattaneo-Mindlin q", \
     F * hertz(x) with lines dt 2 lw 1 lc rgb "#7f7f7f" title "F p (the slip limit)", \
     "output/profile.csv" using ($1 / a):($2 / p0) every ::1 \
       with points pt 7 ps 0.6 lc rgb "#1f77b4" title "l1 at the nodes", \
     "output/profile.csv" using ($1 / a):($3 / p0) every ::1 \
       with points pt 5 ps 0.6 lc rgb "#2ca02c" title "l2_x at the nodes"

set output "zones.svg"
set size ratio -1
set title "The nodes in contact in the plane z = 0: stick and slip"
set xlabel "x / a"
set ylabel "y / a"
set xrange [-1.25:1.25]
set yrange [-1.25:1.25]
set key outside right
set parametric
set trange [0:2 * pi]
plot "output/zones.csv" using ($1 / a):(($3 == 1) ? $2 / a : 1/0) every ::1 \
       with points pt 7 ps 0.4 lc rgb "#1f77b4" title "stick", \
     "output/zones.csv" using ($1 / a):(($3 == 2) ? $2 / a : 1/0) every ::1 \
       with points pt 7 ps 0.4 lc rgb "#d62728" title "slip", \
     cos(t), sin(t) with lines lw 2 lc rgb "#000000" title "r = a", \
     (c / a) * cos(t), (c / a) * sin(t) with lines lw 2 dt 2 lc rgb "#000000" title "r = c"
