# Whole node tick (net in, dynamics, collision, response, apply, events, net out; no rendering)
# against the number of vehicles on the default world, 1 and 2 threads (bench_tick_scaling ->
# tick_scaling.csv; scene and method in bench/bench_tick_scaling.cpp). tick_scaling_before.csv:
# the same bench at c0e5295 (before net out's local-frame bound and the multi-application
# numbering: every vehicle's geodesy every tick, whole tick only up to 20,000).
# tick_scaling_60hz.csv: the same bench with --tick-s 0.0166666666667, each tick stepping 1/60 s
# (the 60 Hz of issue 13's title and TARGETS.md) instead of the 0.1 s of the others.
#   gnuplot bench/results/tick_scaling.gp   (from the repository root)
set terminal pngcairo size 1000,650 font "sans,11"
set output "bench/results/tick_scaling.png"
set datafile separator ","
set logscale xy
set grid
set key top left
set xrange [400:250000]
set format x "%.0s%c"
set xlabel "vehicles N (default world, background traffic spread over the 50 km map)"
set ylabel "median ms per tick (log)"
set title "Node tick against N on the 2-core machine (bench/bench\\_tick\\_scaling.cpp; 0.1 s ticks unless marked)"
old(x) = 0.0005 * x     # the old main: about 0.5 us per vehicle (issue 13, npsnet run --no-render)
frame60(x) = 1000.0 / 60
plot "bench/results/tick_scaling.csv" skip 1 using 1:5 with linespoints pt 7 lw 2 title "whole tick (net in/out), 1 thread", \
     "" skip 1 using 1:6 with linespoints pt 5 lw 2 title "whole tick (net in/out), 2 threads", \
     "" skip 1 using 1:7 with linespoints pt 6 lw 1 dt 2 title "net off, 1 thread", \
     "" skip 1 using 1:8 with linespoints pt 4 lw 1 dt 2 title "net off, 2 threads", \
     "bench/results/tick_scaling_60hz.csv" skip 1 using 1:5 with linespoints pt 9 lw 1 lc rgb "#8c564b" title "whole tick, 1 thread, 60 Hz ticks (1/60 s)", \
     "" skip 1 using 1:6 with linespoints pt 11 lw 1 lc rgb "#1f77b4" title "whole tick, 2 threads, 60 Hz ticks (1/60 s)", \
     "bench/results/tick_scaling_before.csv" skip 1 using 1:($5 > 0 ? $5 : 1/0) with linespoints pt 2 lw 1 lc rgb "gray60" title "whole tick, 1 thread, before (c0e5295)", \
     "bench/results/tick_scaling.csv" skip 1 using 1:13 with lines lw 1 dt 4 lc rgb "dark-green" title "whole tick, 1 thread: CPU ms", \
     old(x) with lines lw 2 dt 3 lc rgb "gray40" title "old main: 0.5 us per vehicle (net off)", \
     frame60(x) with lines lw 1 lc rgb "red" title "16.7 ms (60 Hz)"
