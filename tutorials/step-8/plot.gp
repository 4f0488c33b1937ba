# The figures of step-8 (README.md), from the files the program writes into
# output/: the cycle's steps.csv (one row per step) and contact_step_NNN.csv
# (one row per contact node), and output/figures.gp (their names, the
# clamp's boundary id, F P at +Q*, the stiffness k0 of the first shear step,
# the state after the pressing (file0), and for the three states drawn
# (file1 to file3) Hertz's a and p0 and the traction Mindlin and
# Deresiewicz predict, md1 to md3, in units of F p0 along x/a).
# Run from this folder: gnuplot plot.gp
# q_d / (F p0) at u = x/a for a term of half-width e = d/a
qd(u, e) = abs(u) < e ? sqrt(e**2 - u**2) : 0
load 'output/figures.gp'
set datafile separator ','
set grid

# loop.svg: Q/(F P) against the clamp's displacement, and against the part
# of it that the stiffness of the first shear step does not explain (the
# loop drawn wide)
Q(dummy) = column(sprintf('reaction_%d_x', clamp)) / FP
d(dummy) = 1e3 * column(sprintf('displacement_%d_x', clamp))
set terminal svg size 960,440 dynamic font 'sans,13'
set output 'loop.svg'
set multiplot layout 1,2 title 'Pressed, then sheared twice between +Q* and -Q* (one point per step)'
set key off
set ylabel 'Q / (F P)'
set xlabel 'clamp displacement delta [10^{-3}]'
plot steps using (d(0)):(Q(0)) with linespoints pt 7 ps 0.5 lw 2 lc rgb '#1f77b4'
set xlabel 'delta - Q / k_0 [10^{-3}],  k_0 = Q / delta of the first shear step'
plot steps using (d(0) - 1e3 * Q(0) * FP / k0):(Q(0)) with linespoints pt 7 ps 0.5 lw 2 lc rgb '#d62728'
unset multiplot

# traction.svg: l2/(F p0) along x/a at +Q*, near Q = 0 on unloading and at
# -Q*, the points measured (filled: stick nodes), the lines predicted; in
# black what the pressing left before any shear
set terminal svg size 760,480 dynamic font 'sans,13'
set output 'traction.svg'
set title 'Tangential traction in the cycle: computed (points) and Mindlin-Deresiewicz (lines)'
set xlabel 'x / a'
set ylabel 'l_2 / (F p_0)'
set xrange [-1.15:1.15]
set yrange [-1.15:1.15]
set samples 1001
set key below horizontal maxrows 2 font ',11'
stick(s, y) = s eq 'stick' ? y : 1/0
plot file1 using ($2 / a1):($7 / (F * p01)) with lines dt 3 lc rgb '#7f7f7f' title '±F l_1 at +Q*', \
     ''    using ($2 / a1):(-$7 / (F * p01)) with lines dt 3 lc rgb '#7f7f7f' notitle, \
     file0 using ($2 / a1):($6 / (F * p01)) with linespoints pt 7 ps 0.3 lc rgb '#000000' title sprintf('t = %g, pressed, not sheared', t0), \
     md1(x) with lines lw 2 lc rgb '#1f77b4' title sprintf('t = %g, Q/(F P) = %+.2f', t1, Q1), \
     file1 using ($2 / a1):($6 / (F * p01)) with points pt 6 ps 0.5 lc rgb '#1f77b4' notitle, \
     ''    using ($2 / a1):(stick(strcol(11), $6 / (F * p01))) with points pt 7 ps 0.5 lc rgb '#1f77b4' notitle, \
     md2(x) with lines lw 2 lc rgb '#2ca02c' title sprintf('t = %g, Q/(F P) = %+.2f', t2, Q2), \
     file2 using ($2 / a2):($6 / (F * p02)) with points pt 6 ps 0.5 lc rgb '#2ca02c' notitle, \
     ''    using ($2 / a2):(stick(strcol(11), $6 / (F * p02))) with points pt 7 ps 0.5 lc rgb '#2ca02c' notitle, \
     md3(x) with lines lw 2 lc rgb '#d62728' title sprintf('t = %g, Q/(F P) = %+.2f', t3, Q3), \
     file3 using ($2 / a3):($6 / (F * p03)) with points pt 6 ps 0.5 lc rgb '#d62728' notitle, \
     ''    using ($2 / a3):(stick(strcol(11), $6 / (F * p03))) with points pt 7 ps 0.5 lc rgb '#d62728' notitle
