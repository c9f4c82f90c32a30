# Plots of bench/results/bounds.csv (written by bounds_bench), next to it:
#   gnuplot bench/plot_bounds.gp        (from the repository root)
# Columns: 1 family, 2 size, 3 seed, 4 dim, 5 elements, 6 input_bits,
# 7 reason, 8 reflections, 9 visited, 10 lattice_states, 11 refined_states,
# 12 pieces, 13 visited/lattice, 14 visited/refined, 15 seconds, 16 peak_rss_kb.
set datafile separator ","
set terminal svg size 760,520 dynamic font "sans,12" background rgb "white"
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set key top left box opaque
set grid
# The fifth colour of the default palette (yellow) is too pale on white.
set linetype 5 lc rgb "#404040"
csv = "bench/results/bounds.csv"
structured = "box coprime-box coprime-cuboid square hallway"
random = "random-2d random-3d"
pick(col, f) = strcol(1) eq f ? column(col) : 1/0

set output "bench/results/bounds-lattice.svg"
set title "States visited against the lattice (PSPACE) bound"
set xlabel "lattice bound: integer points on elements x 2^M"
set ylabel "distinct states visited"
plot for [f in structured] csv using (pick(10, f)):(pick(9, f)) skip 1 with linespoints pt 7 ps 0.6 title f, \
     for [f in random] csv using (pick(10, f)):(pick(9, f)) skip 1 with points pt 6 ps 0.8 title f, \
     x with lines dt 2 lc rgb "black" title "visited = bound"

set output "bench/results/bounds-refined.svg"
set title "States visited against the refined (line-invariant) bound"
set xlabel "refined bound: states keeping the start's line invariant"
plot for [f in structured] csv using (pick(11, f)):(pick(9, f)) skip 1 with linespoints pt 7 ps 0.6 title f, \
     for [f in random] csv using (pick(11, f)):(pick(9, f)) skip 1 with points pt 6 ps 0.8 title f, \
     x with lines dt 2 lc rgb "black" title "visited = bound", \
     x / 2 with lines dt 3 lc rgb "gray40" title "visited = bound / 2"

set output "bench/results/bounds-time.svg"
set title "Time to the answer against orbit length"
set xlabel "reflections until the answer (for a cycle: the period)"
set ylabel "solve() wall time, seconds"
set key top left
set yrange [1e-5:100]
plot for [f in structured] csv using (pick(8, f)):(pick(15, f)) skip 1 with linespoints pt 7 ps 0.6 title f, \
     for [f in random] csv using (pick(8, f)):(pick(15, f)) skip 1 with points pt 6 ps 0.8 title f, \
     x / 1e8 with lines dt 2 lc rgb "black" title "1e8 reflections per second"
