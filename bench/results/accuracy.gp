# Speed against accuracy of the collision methods (bench_accuracy -> accuracy.csv).
#   gnuplot bench/results/accuracy.gp   (from the repository root)
set terminal pngcairo size 1400,560 font "sans,11"
set output "bench/results/accuracy.png"
set datafile separator ","
set key off
set logscale x
set xrange [0.05:2000]
set grid
set multiplot layout 1,2 title "Collision methods on random two-vehicle encounters, truth = FCL mesh distance (bench/bench\\_accuracy.cpp)"
set xlabel "time per pair (us, log)"
set ylabel "wrong answers: missed + false-positive rate (%)"
set yrange [0:*]
plot "bench/results/accuracy.csv" skip 1 using 13:(100*($6+$8)) with points pt 7 ps 1.6 lc rgb "#1f77b4", \
     "" skip 1 using 13:(100*($6+$8)):1 with labels offset char 0,1.2 font "sans,9"
set ylabel "contact-point error, median (m, log)"
set logscale y
set format y "%g"
set yrange [*:*]
plot "bench/results/accuracy.csv" skip 1 using 13:9 with points pt 7 ps 1.6 lc rgb "#d62728", \
     "" skip 1 using 13:9:1 with labels offset char 0,1.2 font "sans,9"
unset multiplot
