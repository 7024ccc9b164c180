# One sphere collision step on the default world (40,303 fixed objects) against N moving
# vehicles: ours vs Bullet vs FCL, and our full continuous step (bench_broadphase -> broadphase.csv).
#   gnuplot bench/results/broadphase.gp   (from the repository root)
set terminal pngcairo size 900,600 font "sans,11"
set output "bench/results/broadphase.png"
set datafile separator ","
set logscale xy
set grid
set key top left
set xlabel "moving vehicles N (half spread over 50 km, half in one 2 km square)"
set ylabel "time per step (ms, log)"
set title "Sphere broad + narrow phase, one step (bench/bench\\_broadphase.cpp)"
plot "bench/results/broadphase.csv" skip 1 using 1:3 with linespoints pt 7 lw 2 title "ours (hashed grid + gridsquares)", \
     "" skip 1 using 1:4 with linespoints pt 5 lw 2 title "Bullet 3.24 (btDbvtBroadphase)", \
     "" skip 1 using 1:5 with linespoints pt 9 lw 2 title "FCL 0.7 (DynamicAABBTree)", \
     "" skip 1 using 1:6 with linespoints pt 4 lw 1 dt 2 title "ours, full continuous step (swept, tiers)"
