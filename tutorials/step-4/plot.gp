# The figures of step-4 (README.md), from the CSV files the program writes
# into output/ (one per run, x,l1,l2,theta,status) and output/runs.gp (the
# file names in the order of the runs, Hertz's a and p0 for the prm's nu, F,
# the two Poisson's ratios). Run from this folder: gnuplot plot.gp
load 'output/runs.gp'
set datafile separator ','
set terminal svg size 720,460 dynamic font 'sans,13'
set grid
set xlabel 'x'
set ylabel 'traction'
set samples 1001
hertz(x) = abs(x) < a ? p0 * sqrt(1 - x**2 / a**2) : 0

# The pressure without and with friction, the threshold +-F l1, the
# tangential traction l2 and the sticking nodes: runs 1 and 2 (the prm's
# nu) in hertz_friction.svg, runs 3 and 4 (nu2) in hertz_friction_nu2.svg.
do for [pair = 1:2] {
  set output (pair == 1 ? 'hertz_friction.svg' : 'hertz_friction_nu2.svg')
  set title sprintf('Hertz contact without and with friction F = %g, nu = %g', F, pair == 1 ? nu : nu2)
  set xrange [-1.2 * a:1.2 * a]
  set yrange [-0.4 * p0:2.1 * p0]
  set key top center horizontal maxrows 2 box opaque
  without = 'output/' . word(files, 2 * pair - 1)
  with    = 'output/' . word(files, 2 * pair)
  plot (pair == 1 ? hertz(x) : 1/0) with lines lw 1 lc rgb '#000000' title (pair == 1 ? 'Hertz' : ''), \
       without using 1:2 skip 1 with lines lw 2 dt 2 lc rgb '#7f7f7f' title 'l1, frictionless', \
       with    using 1:2 skip 1 with lines lw 2 lc rgb '#1f77b4' title 'l1, with friction', \
       ''      using 1:4 skip 1 with lines lw 1 dt 3 lc rgb '#d62728' title '±F l1', \
       ''      using 1:(-$4) skip 1 with lines lw 1 dt 3 lc rgb '#d62728' notitle, \
       ''      using 1:3 skip 1 with lines lw 2 lc rgb '#2ca02c' title 'l2, with friction', \
       ''      using 1:($5 == 1 ? $3 : 1/0) skip 1 with points pt 7 ps 0.4 lc rgb '#000000' title 'stick nodes'
}
