set terminal pngcairo size 800,560 enhanced font ',11'
set output './toi-frames.png'
datafile = './toi-frames.dat'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set grid
set xlabel 'c / v'
set ylabel 'difference between contact frames'
set key bottom left
set title 'ball at speed v onto a ball at rest, b = 0.5 (r_0 + r_1)'
plot datafile u 1:2 w lp pt 7 lw 2 lc rgb '#1f77b4' t 'time, table - sphere', '' u 1:5 w lp pt 6 lw 2 lc rgb '#1f77b4' dt 2 t 'normal, table - sphere', '' u 1:4 w lp pt 5 lw 2 lc rgb '#d62728' t 'time, table - zmf', '' u 1:6 w lp pt 4 lw 2 lc rgb '#d62728' dt 2 t 'normal, table - zmf', '' u 1:(0.3*$1**-2) w l dt 3 lc rgb 'black' t '∝ (v/c)^2', '' u 1:(0.3*$1**-4) w l dt 4 lc rgb 'black' t '∝ (v/c)^4'
