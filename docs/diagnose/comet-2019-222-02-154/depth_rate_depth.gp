set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'depth_rate_depth.png'
set grid
set xlabel 'depth rate (m/s, + down)'
set ylabel 'depth (m)'
set yrange [*:*] reverse
plot 'samples.dat' u 3:2 w p pt 7 ps 0.3 t 'measured', '' u 4:2 w p pt 7 ps 0.3 t 'nominal', '' u 5:2 w p pt 7 ps 0.3 t 'extended'
