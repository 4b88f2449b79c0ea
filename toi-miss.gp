set terminal pngcairo size 800,560 enhanced font ',11'
set output './toi-miss.png'
datafile = './toi-miss.dat'
set size ratio -1
set xrange [-1.6:2.9]
set yrange [-1.3:2.6]
unset key
set title 'b = 1.8 r, both at 0.9c: the spheres (dashed) overlap, the contracted balls pass'
set style fill transparent solid 0.25
set label 'ball 0: 0.9c along x' at -1.5,1.2 left tc rgb '#1f77b4'
set label 'ball 1: 0.9c along y' at 0.2,2.45 left tc rgb '#d62728'
plot datafile index 0 w filledcurves lc rgb '#1f77b4', '' index 0 w l lw 2 lc rgb '#1f77b4', '' index 1 w filledcurves lc rgb '#d62728', '' index 1 w l lw 2 lc rgb '#d62728', '' index 2 w l dt 2 lw 1.5 lc rgb '#1f77b4', '' index 3 w l dt 2 lw 1.5 lc rgb '#d62728', '' index 4 u 1:2:3:4 w vectors head filled lw 2 lc rgb 'black'
