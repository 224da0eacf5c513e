set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'drag_change.png'
set grid
set termoption noenhanced
set xlabel 'day of the deployment'
set ylabel 'drag_change (ratio)'
set key top left
plot 'drag_change.dat' u 1:2:3:4 w yerrorbars pt 7 ps 0.6 t 'segments', 'drag_change_shape.dat' u 1:2 w l lw 2 t 'linear'
