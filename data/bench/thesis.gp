set terminal svg size 1100,460 dynamic font 'sans,12'
set datafile missing 'NaN'
kernels = 'exact double'
families = 'uniform-scale uniform-density'
set logscale xy
set xtics (25, 50, 100, 200, 400, 800)
set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
set grid
set key top left
set xlabel 'triangles (log)'
set output 'data/bench/thesis-construction.svg'
set multiplot layout 1,2 title 'KVD construction (Figure 8.4) against the number of triangles, one run'
set ylabel 'construction ms (log)'
do for [f=1:words(families)] {
  set title word(families, f)
  plot for [i=1:words(kernels)] 'data/bench/thesis-plot.dat' index (f-1) using 1:(column(2 + i - 1)) with linespoints pt i ps 1.2 title word(kernels, i)
}
unset multiplot
set output 'data/bench/thesis-update.svg'
set multiplot layout 1,2 title 'average update (Figure 8.6) against the number of triangles, one run'
set ylabel 'average update ms (log)'
do for [f=1:words(families)] {
  set title word(families, f)
  plot for [i=1:words(kernels)] 'data/bench/thesis-plot.dat' index (f-1) using 1:(column(4 + i - 1)) with linespoints pt i ps 1.2 title word(kernels, i)
}
unset multiplot
