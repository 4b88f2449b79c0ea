set terminal pngcairo size 800,560 enhanced font ',11'
set output './classical-2d-limit.png'
datafile = './classical-2d-limit.dat'
set logscale xy
set format y '10^{%L}'
set format x '10^{%L}'
set xrange [1:2000]
set xlabel 'c / v'
set ylabel '|θ_0(c) - θ_0(∞)| (degrees)'
set grid
set key top right
plot datafile u 1:2 w lp pt 7 lw 2 t 'zmf, ε = 1', '' u 1:3 w lp pt 5 lw 2 t 'zmf, ε = 0.5', '' u 1:(30*($1)**-2) w l dt 2 lc rgb 'black' t '∝ (v/c)^2'
