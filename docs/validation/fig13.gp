set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'fig13.png'
set grid
set xlabel 'glide path angle (deg)'
set ylabel 'm/s'
set key top center
set arrow from -25,0 to -25,0.7 nohead dt 2
plot 'fig13.dat' u 1:2 w l lw 2 t 'V', '' u 1:3 w l lw 2 t 'Vx horizontal', '' u 1:4 w l lw 2 t 'Vz depth rate', '-' u 1:2 w p pt 7 ps 1.5 t 'paper: 0.42 / 0.20'
-25 0.42
-25 0.20
e
