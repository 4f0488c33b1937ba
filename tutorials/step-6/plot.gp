# Figures of step-6 from its output folder. Run from this folder after the
# program: gnuplot plot.gp
#   pressure.svg     the contact pressure along Gamma_C against Hertz's
#   stress_axis.svg  the stresses at the probes on the axis against McEwen's
# output/hertz.gp holds a, p0 (Hertz for the measured force) and nu.
load "output/hertz.gp"
set terminal svg size 720,480 dynamic noenhanced font "sans,13"
set datafile separator ","
set grid
set key box opaque

set output "pressure.svg"
set title sprintf("Contact pressure along Γ_C: a = %.5f, p0 = %.4f", a, p0)
set xlabel "x / a"
set ylabel "pressure / p0"
set xrange [-1.5:1.5]
set yrange [0:1.1]
set samples 400
set key bottom center
hertz(x) = abs(x) < 1 ? sqrt(1 - x * x) : 0
plot hertz(x) with lines lw 2 lc rgb "#1f77b4" title "Hertz, p0 sqrt(1 - x²/a²)", \
     "output/pressure.csv" using ($1 / a):($2 / p0) every ::1 \
       with points pt 7 ps 0.6 lc rgb "#d62728" title "l1 at the contact nodes"

set output "stress_axis.svg"
set title "Stresses beneath the centre of the contact (x = 0)"
set xlabel "depth z / a"
set ylabel "stress / p0"
set xrange [0:5.5]
set yrange [-1.05:0.35]
set key bottom right
s(z) = sqrt(1 + z * z)
syy(z) = -1 / s(z)
sxx(z) = -((1 + 2 * z * z) / s(z) - 2 * z)
tau(z) = (sxx(z) - syy(z)) / 2
plot sxx(x) with lines lw 2 lc rgb "#1f77b4" title "σ_xx, McEwen", \
     syy(x) with lines lw 2 lc rgb "#ff7f0e" title "σ_yy, McEwen", \
     tau(x) with lines lw 2 lc rgb "#2ca02c" title "τ = (σ_xx - σ_yy)/2, McEwen", \
     "output/axis.csv" using 2:($3 / p0) every ::1 with points pt 7 lc rgb "#1f77b4" title "σ_xx, probes", \
     "output/axis.csv" using 2:($4 / p0) every ::1 with points pt 5 lc rgb "#ff7f0e" title "σ_yy, probes", \
     "output/axis.csv" using 2:($6 / p0) every ::1 with points pt 9 lc rgb "#2ca02c" title "τ, probes"
