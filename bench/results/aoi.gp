# What one node receives with and without area-of-interest groups, 12 nodes on loopback
# (bench_aoi -> aoi.csv; scene and columns in bench/bench_aoi.cpp). Rows alternate: no AOI, AOI.
#   gnuplot bench/results/aoi.gp   (from the repository root)
set terminal pngcairo size 1200,520 font "sans,11"
set output "bench/results/aoi.png"
set datafile separator ","
set multiplot layout 1,2 title "Area of interest (--aoi 2000, 4096 groups): 12 nodes, 2 vehicles/km^2, each node's vehicles in its own region (bench/bench\\_aoi.cpp)"
set grid
set logscale xy
set xrange [800:25000]
set xtics (1000, 2000, 5000, 10000, 20000)
set xlabel "entities in the exercise"
set key top left
set ylabel "Entity State PDUs received per second by one node (log)"
set title "received per node (mean; max node dashed)"
plot "bench/results/aoi.csv" skip 1 every 2::0 using 1:4 with linespoints pt 7 lw 2 title "one group (no AOI)", \
     "" skip 1 every 2::1 using 1:4 with linespoints pt 5 lw 2 title "AOI, mean node", \
     "" skip 1 every 2::1 using 1:5 with linespoints pt 4 lw 1 dt 2 title "AOI, busiest node"
set ylabel "count per node (log)"
set title "groups joined and entities in them (AOI)"
plot "" skip 1 every 2::1 using 1:7 with linespoints pt 7 lw 2 title "groups joined", \
     "" skip 1 every 2::1 using 1:8 with linespoints pt 5 lw 2 title "other nodes' entities in joined cells", \
     "" skip 1 every 2::0 using 1:8 with linespoints pt 9 lw 1 dt 2 title "other nodes' entities (no AOI: all)"
unset multiplot
