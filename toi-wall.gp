set terminal pngcairo size 800,560 enhanced font ',11'
set output './toi-wall.png'
datafile = './toi-wall.dat'
set terminal pngcairo size 1100,460 enhanced font ',11'
set multiplot layout 1,2
set logscale x
set format x '10^{%L}'
set grid
set xlabel 'c / |v|'
set ylabel 't / t_{sphere}'
set title 'wall one radius away, speed |v| at angle φ to its normal'
set key top right
set xrange [1:1000]
plot for [i=0:3] datafile u 1:2+2*i w l lw 2 lc i+1 t sprintf('φ = %s°', word('0 45 60 75', i+1))
set title 'delay against the uncontracted sphere'
set logscale y
set format y '10^{%L}'
set ylabel 't - t_{sphere}  (units r / |v|)'
plot for [i=0:3] datafile u 1:3+2*i w l lw 2 lc i+1 t sprintf('φ = %s°', word('0 45 60 75', i+1)), datafile u 1:(0.5/$1**2) w l dt 2 lw 1.5 lc rgb 'black' t 'r (v·n) / (2c^2) at φ = 0'
unset multiplot
