set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'pitch_time.png'
set grid
set xlabel 'minutes'
set ylabel 'pitch (deg, + nose up)'
plot 'pitch.dat' u 1:3 w p pt 7 ps 0.3 t 'measured', '' u 1:4 w p pt 7 ps 0.3 t 'nominal', '' u 1:5 w p pt 7 ps 0.3 t 'extended'
