set terminal svg size 760,480 dynamic font 'sans,12'
set output 'data/bench/update.svg'
set datafile missing 'NaN'
set logscale xy
set xtics (100, 200, 400, 800, 1600, 3200)
set xrange [83.3:3840.0]
set grid
set key top left
set title 'Mean update per batch, uniform-scale, all moving, one run'
set xlabel 'triangles (log)'
set ylabel 'ms per batch (log)'
plot 'data/bench/update-plot.dat' using 1:2 with linespoints pt 1 ps 1.2 title 'local', 'data/bench/update-plot.dat' using 1:3 with linespoints pt 2 ps 1.2 title 'reinsert', 'data/bench/update-plot.dat' using 1:4 with linespoints pt 3 ps 1.2 title 'local, double', 'data/bench/update-plot.dat' using 1:5 with linespoints pt 4 ps 1.2 title 'rebuild'
