set terminal svg size 760,480 dynamic font 'sans,12'
set output 'data/bench/cost.svg'
set datafile missing 'NaN'
set logscale x
set yrange [0:*]
set xtics (25, 50, 100, 200, 400, 800)
set xrange [20.8:960.0]
set grid
set key top left
set title 'Exact against double, uniform-scale, all moving (medians of 3)'
set xlabel 'triangles (log)'
set ylabel 'exact / double'
plot 'data/bench/cost-plot.dat' using 1:2 with linespoints pt 1 ps 1.2 title 'build', 'data/bench/cost-plot.dat' using 1:3 with linespoints pt 2 ps 1.2 title 'per event', 1.5 with lines dt 2 lc 'gray' title '1.5'
