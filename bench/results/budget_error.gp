# Accuracy against the collision budget of the scene-aware auto tier: a crowd nobody watches, one
# tick, FCL as the oracle (bench_budget_error -> budget_error.csv, vehicle-vs-vehicle, top row;
# bench_budget_error --fixed --vehicles 10000 --side 1600 -> budget_error_fixed.csv,
# vehicle-vs-fixed, bottom row; scenes and columns in bench/bench_budget_error.cpp). Budget 0 is
# drawn at 0.03 ms.
#   gnuplot bench/results/budget_error.gp   (from the repository root)
set terminal pngcairo size 1200,980 font "sans,11"
set output "bench/results/budget_error.png"
set datafile separator ","
set multiplot layout 2,2 title "Scene-aware auto tier: error against the per-tick budget (bench/bench\\_budget\\_error.cpp)"
set grid
set logscale x
set xrange [0.02:500]
set xtics ("0" 0.03, "0.1" 0.1, "0.3" 0.3, "1" 1, "3" 3, "10" 10, "30" 30, "100" 100, "300" 300)
set xlabel "collision\\_budget\\_ms (modelled narrow-phase time per tick)"
set key top right
b(x) = x > 0 ? x : 0.03
do for [which in "vehicle-vehicle vehicle-fixed"] {
  f = which eq "vehicle-vehicle" ? "bench/results/budget_error.csv" : "bench/results/budget_error_fixed.csv"
  unset logscale y
  set key at graph 0.03, 0.86 left top Left reverse
  set ylabel "pairs"
  set title which . ": false positives and misses against FCL, pairs lowered"
  plot f skip 1 using (b($1)):6 with linespoints pt 7 lw 2 title "false positives", \
       f skip 1 using (b($1)):7 with linespoints pt 5 lw 2 title "misses", \
       f skip 1 using (b($1)):3 with linespoints pt 4 lw 1 dt 2 title "pairs lowered below exact tier", \
       f skip 1 using (b($1)):5 with lines lw 1 dt 3 lc rgb "gray40" title "FCL contacts (truth)"
  set logscale y
  set key default
  set key inside bottom left Left reverse
  set ylabel "contact point error (m, log)"
  set title which . ": contact point error, contacts both find"
  plot f skip 1 using (b($1)):8 with linespoints pt 7 lw 2 title "median", \
       f skip 1 using (b($1)):9 with linespoints pt 5 lw 2 title "95th percentile"
}
unset multiplot
