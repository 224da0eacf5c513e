set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'speed_time.png'
set grid
set xlabel 'minutes'
set ylabel 'speed through water (m/s)'
plot 'speed.dat' u 1:3 w p pt 7 ps 0.3 t 'measured', '' u 1:4 w p pt 7 ps 0.3 t 'nominal', '' u 1:5 w p pt 7 ps 0.3 t 'extended'
