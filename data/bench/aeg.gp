set terminal svg size 760,1260 dynamic font 'sans,12'
set output 'data/bench/aeg.svg'
set multiplot layout 3,1
unset logscale
set autoscale y
set datafile missing 'NaN'
set logscale x
set yrange [0:*]
set xtics (100, 200, 400, 800, 1600, 3200, 6400, 12800)
set xrange [83.3:15360.0]
set grid
set key bottom right
set title 'Static BSP: size against n log2 n + k (Theorem 2.3)'
set xlabel 'segments (log)'
set ylabel 'nodes / (n log2 n + k)'
plot 'data/bench/aeg-static.dat' using 1:2 with linespoints pt 1 ps 1.2 title 'k = O(n)', 'data/bench/aeg-static.dat' using 1:3 with linespoints pt 2 ps 1.2 title 'k = Θ(n²)'
unset logscale
set autoscale y
set datafile missing 'NaN'
set logscale x
set yrange [0:*]
set xtics (100, 200, 400, 800, 1600, 3200, 6400, 12800)
set xrange [83.3:15360.0]
set grid
set key bottom right
set title 'Static BSP: height against log2 n (Theorem 2.3)'
set xlabel 'segments (log)'
set ylabel 'height / log2 n'
plot 'data/bench/aeg-static.dat' using 1:4 with linespoints pt 1 ps 1.2 title 'k = O(n)', 'data/bench/aeg-static.dat' using 1:5 with linespoints pt 2 ps 1.2 title 'k = Θ(n²)'
unset logscale
set autoscale y
set datafile missing 'NaN'
set logscale xy
set xtics (100, 200, 400, 800, 1600, 3200, 6400, 12800)
set xrange [83.3:15360.0]
set grid
set key top left
set title 'Kinetic BSP: mean update per batch, exact, first 50 failures'
set xlabel 'segments (log)'
set ylabel 'ms per batch (log)'
plot 'data/bench/aeg-kinetic.dat' using 1:2 with linespoints pt 1 ps 1.2 title 'local, m = n', 'data/bench/aeg-kinetic.dat' using 1:3 with linespoints pt 2 ps 1.2 title 'subtree, m = n', 'data/bench/aeg-kinetic.dat' using 1:4 with linespoints pt 3 ps 1.2 title 'rebuild, m = n', 'data/bench/aeg-kinetic.dat' using 1:5 with linespoints pt 4 ps 1.2 title 'local, m = n/2', 'data/bench/aeg-kinetic.dat' using 1:6 with linespoints pt 5 ps 1.2 title 'rebuild, m = n/2'
unset multiplot
