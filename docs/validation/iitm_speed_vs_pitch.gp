set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'iitm_speed_vs_pitch.png'
set grid
set xlabel 'pitch (deg)'
set ylabel 'speed through water (m/s)'
plot 'iitm_speed_vs_pitch.dat' u 1:2 w l lw 2 t 'model, Delta B = 0.3 kg', '-' u 1:2 w p pt 7 ps 1.5 t 'paper'
-37 0.198
e
