set terminal pngcairo size 800,560 enhanced font ',11'
set output './classical-2d-deflection.png'
datafile = './classical-2d-deflection.dat'
set terminal pngcairo size 1100,480 enhanced font ',11'
set multiplot layout 1,2
set xlabel 'impact parameter b / (r_0 + r_1)'
set ylabel 'deflection of ball 0, θ_0 (degrees)'
set grid
set key top right font ',10' spacing 1.1
set yrange [0:140]
set ytics 0,10,90
set title 'c = ∞: the three seeds and relcol'
plot datafile u 1:5 w l lw 6 lc rgb '#bbbbbb' t 'relcol zmf, ε = 1 and 0.5', '' every 6 u 1:2 w p pt 6 ps 1.2 lc rgb '#1f77b4' t 'seed 000 collide', '' every 6::2 u 1:3 w p pt 4 ps 1.2 lc rgb '#d62728' t 'seed 001 collision', '' every 6::4 u 1:4 w p pt 8 ps 1.2 lc rgb '#2ca02c' t 'seed 002 (8)-(13)', '' u 1:7 w l lw 6 lc rgb '#bbbbbb' dt 1 notitle, '' every 6 u 1:6 w p pt 7 ps 0.9 lc rgb '#1f77b4' t 'seed 000, ε = 0.5 (= zmf)', '' u 1:9 w l lw 2 lc rgb '#2ca02c' dt 2 t 'relcol cm-isotropic, R = 0.5', '' every 6::3 u 1:8 w p pt 9 ps 1.2 lc rgb '#2ca02c' t 'seed 002, R = 0.5'
set key top right font ',11'
set yrange [0:95]
set title 'relcol zmf law: c = ∞ against c = 2v (same normal)'
plot datafile u 1:5 w l lw 2 lc rgb '#1f77b4' t 'c = ∞, ε = 1', '' u 1:10 w l lw 2 lc rgb '#d62728' t 'c = 2v, ε = 1', '' u 1:7 w l lw 2 dt 2 lc rgb '#1f77b4' t 'c = ∞, ε = 0.5', '' u 1:11 w l lw 2 dt 2 lc rgb '#d62728' t 'c = 2v, ε = 0.5'
unset multiplot
