set terminal pngcairo size 900,560 font 'DejaVu Sans,10'
set output 'buoyancy_offset.png'
set grid
set termoption noenhanced
set xlabel 'day of the deployment'
set ylabel 'buoyancy_offset (g)'
set key top left
plot 'buoyancy_offset.dat' u 1:2:3:4 w yerrorbars pt 7 ps 0.6 t 'segments', 'buoyancy_offset_shape.dat' u 1:2 w l lw 2 t 'step'
