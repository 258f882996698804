set terminal svg size 1100,460 dynamic enhanced font 'sans,12'
set output 'data/bench/accuracy.svg'
set datafile separator ','
set datafile missing 'NaN'
kernels = 'double mpfr:24 mpfr:53 mpfr:113 mpfr:256 mpfr:1024 exact'
inexact = 'double mpfr:24 mpfr:53 mpfr:113 mpfr:256 mpfr:1024'
set multiplot layout 1,2 title 'Floating-point kernels against the exact kernel (100 exact events per scene, one point per kernel and scene)'
set logscale x
set format x '10^{%L}'
set grid
set xlabel 'seconds per event (log)'
set key bottom left
set ylabel 'log10 of the largest relative event-time error'
plot for [i=1:words(inexact)] 'data/bench/accuracy.csv' skip 1 using (strcol(2) eq word(inexact, i) ? column(5) : NaN):(column(8)) with points pt i ps 1.2 title word(inexact, i)
set ylabel 'share of exact events not reproduced'
set yrange [-0.05:1.05]
set key top right
plot for [i=1:words(kernels)] 'data/bench/accuracy.csv' skip 1 using (strcol(2) eq word(kernels, i) ? column(5) : NaN):(column(14)) with points pt i ps 1.2 title word(kernels, i)
unset multiplot
