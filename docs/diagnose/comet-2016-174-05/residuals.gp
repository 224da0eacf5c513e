set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'residuals.png'
set grid
set xlabel 'residual (m/s)'
set ylabel 'depth (m)'
set yrange [*:*] reverse
plot 'samples.dat' u 6:2 w p pt 7 ps 0.3 t 'nominal model', '' u 7:2 w p pt 7 ps 0.3 t 'extended model'
