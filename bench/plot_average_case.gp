# Plots of the average-case experiments (docs/average-case.md), next to
# their tables:   gnuplot bench/plot_average_case.gp   (from the repository root)
# bench/results/average-case.csv (average_case): 1 spheres, 2 s/r, 3 rays,
#   4 mean tests, 5 (1 + s/r)^2, 6 ratio, 7 P(tests = 1), 8 q.
# bench/results/grid-average.csv (grid_average): 1 dim, 2 mirrors,
#   3 structure, 4 cells per element, 10 tests, 11 tests by the model.
set datafile separator ","
set terminal svg size 760,520 dynamic font "sans,12" background rgb "white"
set key top left box opaque
set grid
set linetype 5 lc rgb "#404040"
spheres = "average-case"
pick(col, n) = column(1) == n ? column(col) : 1/0

# Mean tests to the first hit against s/r: the lecture's (1 + s/r)^2 and the
# estimate of docs/average-case.md with the column's cross-section.
set output "bench/results/average-case-mean.svg"
set logscale xy
set xlabel "cell diagonal / sphere radius (s/r)"
set ylabel "spheres tested per ray until the first hit"
set xrange [0.08:12]
set title "Uniform grid over Poisson spheres: mean tests (4,000 rays a point)"
plot (1 + x)**2 title "lecture: (1 + s/r)^2" lw 2 lc rgb "#c00000", \
     1 + 1.5*x + x**2 / (2*pi) title "column estimate: 1 + 1.5 s/r + (s/r)^2 / 2pi" dt 2 lw 2 lc rgb "#606060", \
     "bench/results/average-case.csv" using 2:(pick(4, 1000)) title "n = 10^3" with points pt 7 ps 0.8, \
     "" using 2:(pick(4, 10000)) title "n = 10^4" with points pt 5 ps 0.8, \
     "" using 2:(pick(4, 100000)) title "n = 10^5" with points pt 9 ps 0.9

# P(first test hits) against q = (r / (r + s))^2: on the diagonal where the
# count is geometric.
set output "bench/results/average-case-first.svg"
unset logscale
set xrange [0:1]
set yrange [0:1]
set xlabel "q = (r / (r + s))^2"
set ylabel "measured P(tests = 1)"
set title "Is the count geometric? P(first sphere tested is hit) against q"
plot x title "geometric law" lw 2 lc rgb "#c00000", \
     "bench/results/average-case.csv" using 8:(pick(7, 1000)) title "n = 10^3" with points pt 7 ps 0.8, \
     "" using 8:(pick(7, 10000)) title "n = 10^4" with points pt 5 ps 0.8, \
     "" using 8:(pick(7, 100000)) title "n = 10^5" with points pt 9 ps 0.9

# orthoray's own grids: tests per shot against cells per element, measured
# and by the model, at 10^5 random mirrors.
set output "bench/results/grid-average-tests.svg"
set logscale xy
set autoscale
set xlabel "grid cells per element"
set ylabel "elements tested per shot"
set title "orthoray's grids at 10^5 random mirrors: measured (points) and model (lines)"
grid(col, d, s) = (column(1) == d && column(2) == 100000 && strcol(3) eq s) ? column(col) : 1/0
plot "bench/results/grid-average.csv" using 4:(grid(10, 2, "uniform")) title "2D uniform" with points pt 7 lc 1, \
     "" using 4:(grid(11, 2, "uniform")) notitle with lines lc 1, \
     "" using 4:(grid(10, 3, "uniform")) title "3D uniform" with points pt 5 lc 2, \
     "" using 4:(grid(11, 3, "uniform")) notitle with lines lc 2, \
     "" using 4:(grid(10, 2, "section")) title "2D cross-section" with points pt 9 lc 3, \
     "" using 4:(grid(11, 2, "section")) notitle with lines lc 3, \
     "" using 4:(grid(10, 3, "section")) title "3D cross-section" with points pt 11 lc 4, \
     "" using 4:(grid(11, 3, "section")) notitle with lines lc 4
