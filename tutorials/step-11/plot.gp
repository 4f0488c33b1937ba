# The figures of step-11 (README.md), from the files the program writes into
# output/: the library's contact_NN.csv and contact_step_NNN.csv of each run
# (one row per slave node: x, weight, l1, l2, status, ...), master_forces.csv
# (the forces of a uniform pressure on the master nodes, both couplings),
# and figures.gp (the files' names, Hertz's a and p0 of each pair, and for
# three states of the cycle the file, a, p0, Q/(F P) and the traction
# Masing's rule predicts, md1 to md3, in units of F p0 along x/a).
# Run from this folder after the program: gnuplot plot.gp
#   patch.svg     the patch test: l1 at the slave nodes, dual mortar and
#                 node to segment, on both meshes; the forces of p = 1 on
#                 the master nodes over the consistent load int p phi_j
#   pressure.svg  two cylinders: l1/p0 along x/a against Hertz, both pairs
#   traction.svg  the cycle: the tangential traction at +Q*, near Q = 0 and
#                 at -Q* against Cattaneo, Mindlin and Deresiewicz
# q_d / (F p0) at u = x/a for a term of half-width e = d/a
qd(u, e) = abs(u) < e ? sqrt(e**2 - u**2) : 0
load 'output/figures.gp'
set datafile separator ','
set grid

# ---------------------------------------------------------------- patch.svg
set terminal svg size 960,460 dynamic font 'sans,13'
set output 'patch.svg'
set multiplot layout 1,2 title 'The patch test, 7 over 10 cells (then 14 over 20), uniform pressure p = 1'
set title 'the pressure at the slave nodes'
set xlabel 'x'
set ylabel 'l_1 / p'
set xrange [-0.05:2.05]
set yrange [0.8:1.2]
set key below horizontal maxcols 2 font ',10'
plot patch00 using 'x':'l1' with linespoints pt 7 ps 0.6 lw 2 lc rgb '#1f77b4' title 'dual mortar, 7 over 10', \
     patch01 using 'x':'l1' with linespoints pt 6 ps 0.6 lw 1 dt 2 lc rgb '#1f77b4' title 'dual mortar, 14 over 20', \
     patch10 using 'x':'l1' with linespoints pt 7 ps 0.6 lw 2 lc rgb '#d62728' title 'node to segment, 7 over 10', \
     patch11 using 'x':'l1' with linespoints pt 6 ps 0.6 lw 1 dt 2 lc rgb '#d62728' title 'node to segment, 14 over 20'
set title 'the forces on the master nodes (7 over 10)'
set ylabel 'f_j / \int p {/Symbol f}_j'
set yrange [0.6:1.5]
set key below horizontal font ',10'
plot forces using 'x':(column('mortar') / column('consistent')) with linespoints pt 7 ps 0.6 lw 2 lc rgb '#1f77b4' title 'dual mortar', \
     forces using 'x':(column('node_to_segment') / column('consistent')) with linespoints pt 7 ps 0.6 lw 2 lc rgb '#d62728' title 'node to segment'
unset multiplot

# ------------------------------------------------------------- pressure.svg
set terminal svg size 760,480 dynamic font 'sans,13'
set output 'pressure.svg'
set title 'Two cylinders, frictionless: the pressure on the slave surface (second mesh) against Hertz'
set xlabel 'x / a'
set ylabel 'l_1 / p_0'
set xrange [-1.3:1.3]
set yrange [0:1.1]
set samples 1001
set key inside bottom center box opaque font ',11'
plot (abs(x) < 1 ? sqrt(1 - x**2) : 0) with lines lw 2 lc rgb '#000000' title 'Hertz, a and p_0 from E* and R*', \
     hertz0 using (column('x') / ha0):(column('l1') / hp0) with points pt 7 ps 0.5 lc rgb '#1f77b4' title hname0, \
     hertz1 using (column('x') / ha1):(column('l1') / hp1) with points pt 6 ps 0.7 lc rgb '#d62728' title hname1

# ------------------------------------------------------------- traction.svg
set terminal svg size 760,480 dynamic font 'sans,13'
set output 'traction.svg'
set title 'Two cylinders, Q1, nu = 0.3: computed traction (points) and Mindlin-Deresiewicz (lines)'
set xlabel 'x / a'
set ylabel 'q / (F p_0)'
set xrange [-1.15:1.15]
set yrange [-1.15:1.15]
set key below horizontal maxrows 2 font ',11'
stick(s, y) = s eq 'stick' ? y : 1/0
plot file1 using (column('x') / a1):(column('l1') / p01) with lines dt 3 lc rgb '#7f7f7f' title '±F l_1', \
     ''    using (column('x') / a1):(-column('l1') / p01) with lines dt 3 lc rgb '#7f7f7f' notitle, \
     md1(x) with lines lw 2 lc rgb '#1f77b4' title sprintf('t = %g, Q/(F P) = %+.2f', t1, Q1), \
     file1 using (column('x') / a1):(sign * column('l2') / (F * p01)) with points pt 6 ps 0.5 lc rgb '#1f77b4' notitle, \
     ''    using (column('x') / a1):(stick(strcol(11), sign * column('l2') / (F * p01))) with points pt 7 ps 0.5 lc rgb '#1f77b4' notitle, \
     md2(x) with lines lw 2 lc rgb '#2ca02c' title sprintf('t = %g, Q/(F P) = %+.2f', t2, Q2), \
     file2 using (column('x') / a2):(sign * column('l2') / (F * p02)) with points pt 6 ps 0.5 lc rgb '#2ca02c' notitle, \
     ''    using (column('x') / a2):(stick(strcol(11), sign * column('l2') / (F * p02))) with points pt 7 ps 0.5 lc rgb '#2ca02c' notitle, \
     md3(x) with lines lw 2 lc rgb '#d62728' title sprintf('t = %g, Q/(F P) = %+.2f', t3, Q3), \
     file3 using (column('x') / a3):(sign * column('l2') / (F * p03)) with points pt 6 ps 0.5 lc rgb '#d62728' notitle, \
     ''    using (column('x') / a3):(stick(strcol(11), sign * column('l2') / (F * p03))) with points pt 7 ps 0.5 lc rgb '#d62728' notitle
