# tsweep.gp — papers/transport.md §12's figure: eta and lambda of relcol-eos --transport
# (Einstein–Helfand, c = 1, packing 0.005, N = 500, seed 1; zmf at lag 40, the others at lag 10) over theta = 0.01 ... 100 per
# contact frame, over the invariant Boltzmann gas's converged Chapman–Enskog value
# (apps/eos/ce_rel.c); the sphere frame also over its own kernel's (papers/transport.md §4).
#   gnuplot -e "csv='data/reproductions/ghodrat2020.csv'; out='tsweep.png'" papers/scripts/tsweep.gp
if (!exists("csv")) csv = 'data/reproductions/ghodrat2020.csv'
if (!exists("out")) out = 'tsweep.png'
set terminal pngcairo size 1400,600 enhanced font 'Sans,12' linewidth 1.4
set output out
set datafile separator ','
# column 22 is the lag: 10 (transport, sphere), 40 (zmf); the lag-160 zmf rows are a lag study, not drawn
sel(f) = (strcol(1) eq f && $2 == 500 && $5 == 1 && $22 <= 40)
set multiplot layout 1,2 title "Transport of the dilute relativistic hard-ball gas by contact frame: relcol-eos --transport, c = 1, packing 0.005, N = 500, 16000 mean free times\n{/*0.8 Helfand lag 10 (transport, sphere) and 40 (zmf) mean free times; error bars: one standard error over 40 blocks}\n{/*0.8 reference: the invariant Boltzmann gas (Møller rate, isotropic CM cross-section π d^2), converged Chapman–Enskog (16 functions)}"
set logscale xy
set xrange [0.006:160]
set yrange [0.6:100]
set xlabel 'θ = kT/(mc^2)'
set grid lc rgb '#dddddd'
set key top left Left reverse box opaque font ',10' samplen 2
do for [q = 0:1] {
    c = q == 0 ? 10 : 12; r16 = q == 0 ? 15 : 17; r1 = q == 0 ? 14 : 16; own = q == 0 ? 18 : 19
    set ylabel (q == 0 ? 'η / η_{CE, invariant}' : 'λ / λ_{CE, invariant}')
    set title (q == 0 ? 'shear viscosity' : 'heat conductivity (Eckart)')
    plot 1 with lines lc rgb '#444444' title 'invariant gas, converged (the reference)', \
         csv skip 1 using (sel('transport') ? $4 : NaN):(column(r1)/column(r16)) with linespoints dt 2 pt 0 lc rgb '#444444' title 'invariant gas, first order (de Groot et al.)', \
         csv skip 1 using (sel('transport') ? $4 : NaN):(column(c)/column(r16)):(column(c+1)/column(r16)) with yerrorbars pt 7 ps 1.2 lc rgb '#1f77b4' title 'frame transport (points, invariant σ)', \
         csv skip 1 using (sel('zmf') ? $4*1.08 : NaN):(column(c)/column(r16)):(column(c+1)/column(r16)) with yerrorbars pt 5 ps 1.1 lc rgb '#d62728' title 'frame zmf (θ ≥ 10: lag-limited, a lower bound)', \
         csv skip 1 using (sel('sphere') ? $4/1.08 : NaN):(column(c)/column(r16)):(column(c+1)/column(r16)) with yerrorbars pt 9 ps 1.2 lc rgb '#2ca02c' title 'frame sphere (table-frame rate)', \
         csv skip 1 using (sel('sphere') ? $4/1.08 : NaN):(column(own)/column(r16)) with linespoints dt 3 pt 0 lc rgb '#2ca02c' title "sphere kernel's own Chapman–Enskog"
}
unset multiplot
