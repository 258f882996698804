set terminal svg size 760,840 dynamic font 'sans,12'
set output 'data/bench/aeg-cost.svg'
set multiplot layout 2,1
unset logscale
set autoscale y
set datafile missing 'NaN'
set logscale xy
set xtics (100, 200, 400, 800, 1600, 3200, 6400, 12800)
set xrange [83.3:15360.0]
set grid
set key top left
set title 'Signs per batch, first 2000 failures'
set xlabel 'segments (log)'
set ylabel 'signs per batch (log)'
plot 'data/bench/aeg-cost.dat' using 1:2 with linespoints pt 1 ps 1.2 title 'decided: local, m = n', 'data/bench/aeg-cost.dat' using 1:3 with linespoints pt 2 ps 1.2 title 'decided: local, m = n/2', 'data/bench/aeg-cost.dat' using 1:4 with linespoints pt 3 ps 1.2 title 'decided: paper, m = n', 'data/bench/aeg-cost.dat' using 1:5 with linespoints pt 4 ps 1.2 title 'decided: paper, m = n/2', 'data/bench/aeg-cost.dat' using 1:6 with linespoints pt 5 ps 1.2 title 'held: local, m = n', 'data/bench/aeg-cost.dat' using 1:7 with linespoints pt 6 ps 1.2 title 'held: local, m = n/2'
unset logscale
set autoscale y
set datafile missing 'NaN'
set logscale x
set yrange [0:*]
set xtics (100, 200, 400, 800, 1600, 3200, 6400, 12800)
set xrange [83.3:15360.0]
set grid
set key top left
set title 'Nodes made again per batch'
set xlabel 'segments (log)'
set ylabel 'nodes per batch'
plot 'data/bench/aeg-cost.dat' using 1:8 with linespoints pt 1 ps 1.2 title 'local, m = n', 'data/bench/aeg-cost.dat' using 1:9 with linespoints pt 2 ps 1.2 title 'local, m = n/2', 'data/bench/aeg-cost.dat' using 1:10 with linespoints pt 3 ps 1.2 title 'paper, m = n', 'data/bench/aeg-cost.dat' using 1:11 with linespoints pt 4 ps 1.2 title 'paper, m = n/2'
unset multiplot
