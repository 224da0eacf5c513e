set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'pitch_depth.png'
set grid
set xlabel 'pitch (deg)'
set ylabel 'depth (m)'
set yrange [*:*] reverse
plot 'pitch.dat' u 3:2 w p pt 7 ps 0.3 t 'measured', '' u 4:2 w p pt 7 ps 0.3 t 'nominal', '' u 5:2 w p pt 7 ps 0.3 t 'extended'
