# Plots of bench/results/induction.csv (written by induction_bench), next to it:
#   gnuplot bench/plot_induction.gp        (from the repository root)
# Columns: 1 family, 2 param, 3 elements, 4 engine, 5 reason, 6 reflections,
# 7 log10_reflections, 8 runs, 9 median_seconds, 10 pieces (k),
# 11 log2_states (log2 N), 12 steps, 13 rounds, 14 k_log2_states,
# 15 steps_over_k_log2_states, 16 induction_seconds.
# Reflections are plotted as 10^column 7: column 6 is exact and may exceed
# what a double holds exactly (it is up to about 10^30).
set datafile separator ","
set terminal svg size 760,520 dynamic font "sans,12" background rgb "white"
set logscale xy
set format x "10^{%T}"
set format y "10^{%T}"
set key bottom right box opaque
set grid
set linetype 5 lc rgb "#404040"
csv = "bench/results/induction.csv"
families = "coprime-box fibonacci-box hallway random-100 random-1000"
# The value of column `col` on rows of family f and engine e, else no point.
pick(col, f, e) = (strcol(1) eq f && strcol(4) eq e) ? column(col) : 1/0
refl(f, e) = (strcol(1) eq f && strcol(4) eq e) ? 10**column(7) : 1/0

set xlabel "reflections until the answer (for a cycle: the period)"
set ylabel "solve() wall time, seconds (median)"
# Fixed ranges: the plots compare across families, and a family missing from
# a --quick run leaves an empty plot rather than an error.
set xrange [10:1e31]
set yrange [1e-6:100]
do for [f in families] {
    set output "bench/results/induction-time-".f.".svg"
    set title "Time against reflections: ".f
    plot csv using (refl(f, "induction")):(pick(9, f, "induction")) skip 1 \
             with linespoints pt 7 ps 0.6 lc 1 title "induction", \
         csv using (refl(f, "lattice")):(pick(9, f, "lattice")) skip 1 \
             with linespoints pt 5 ps 0.6 lc 2 title "simulation (lattice)", \
         x / 1e8 with lines dt 2 lc rgb "black" title "1e8 reflections per second"
}

set output "bench/results/induction-time.svg"
set title "Time against reflections, all families (filled: induction, open: simulation)"
plot for [i=1:words(families)] csv using (refl(word(families, i), "induction")):(pick(9, word(families, i), "induction")) skip 1 \
         with points pt 7 ps 0.6 lc i title word(families, i), \
     for [i=1:words(families)] csv using (refl(word(families, i), "lattice")):(pick(9, word(families, i), "lattice")) skip 1 \
         with points pt 6 ps 0.7 lc i notitle, \
     x / 1e8 with lines dt 2 lc rgb "black" title "1e8 reflections per second"

set autoscale xy
set output "bench/results/induction-steps.svg"
set title "Induction steps against k log2 N (k pieces, N states)"
set xlabel "k log2 N"
set ylabel "induction steps (an accelerated step counts once)"
plot for [f in families] csv using (pick(14, f, "induction")):(pick(12, f, "induction")) skip 1 \
         with points pt 7 ps 0.6 title f, \
     x with lines dt 2 lc rgb "black" title "steps = k log2 N", \
     x / 10 with lines dt 3 lc rgb "gray40" title "steps = k log2 N / 10"
