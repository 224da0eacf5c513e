set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'real_depth_rate.png'
set grid
set xlabel 'minutes into the log'
set ylabel 'depth rate (m/s, + down)'
plot 'real_depth_rate.dat' u 1:2 w p pt 7 ps 0.4 t 'measured', '' u 1:3 w p pt 7 ps 0.4 t 'nominal model'
