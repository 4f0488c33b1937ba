# The figures of step-1 (run from tutorials/step-1 after the program):
#   pressure.svg           computed contact pressure l1 at the contact nodes
#                          against Hertz's p(x) = p0 sqrt(1 - x^2/a^2)
#   uzawa_convergence.svg  d(l1) per Uzawa step for r_rel = 0.1, 1, 10, 100
set datafile separator ','
set terminal svg size 720,480 dynamic font 'Helvetica,14'

# Hertz, plane strain, from the data of step-1.prm (doc/theory.md §9)
E  = 1000.; nu = 0.3; R = 1.; P = 2 * R * 4.315374524161804
Es = E / (1 - nu**2)
a  = sqrt(4 * P * R / (pi * Es))
p0 = 2 * P / (pi * a)
hertz(x) = abs(x) < a ? p0 * sqrt(1 - x**2 / a**2) : 0

set output 'pressure.svg'
set title sprintf('Frictionless Hertz contact: P = %.4f, a = %.4f, p0 = %.3f', P, a, p0)
set xlabel 'x (along the plane)'
set ylabel 'contact pressure'
set xrange [-0.14:0.14]
set yrange [0:72]
set samples 2001
set key top left Left reverse
set grid
plot hertz(x) with lines lw 2 lc rgb '#1f77b4' title 'Hertz p(x)', \
     'output/pressure.csv' using 1:2 every ::1 with points pt 7 ps 0.6 \
        lc rgb '#d62728' title 'l1 at the contact nodes (r_{rel} = 10)'

set output 'uzawa_convergence.svg'
set title 'Uzawa iteration: relative change of l1 per step'
set xlabel 'Uzawa step k'
set ylabel 'd(l1)'
set logscale y
set format y '10^{%L}'
set xrange [1:80]
set yrange [1e-10:2]
unset samples
set key top right
tolerance = 1e-8
plot for [r in '0.1 1 10 100'] 'output/uzawa_convergence.csv' \
       using 2:(abs($1 - real(r)) < 1e-12 * real(r) ? $3 : 1/0) every ::1 \
       with linespoints pt 7 ps 0.5 title sprintf('r_{rel} = %s', r), \
     tolerance with lines dt 2 lc rgb 'black' title 'Uzawa tolerance'
