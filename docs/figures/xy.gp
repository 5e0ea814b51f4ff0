# Made by figure-xy (tests/bench/figure_xy.cpp) for scripts/figures.sh.
set encoding utf8
set terminal svg size 900,700 dynamic font 'sans,12'
set output 'docs/figures/xy.svg'
set logscale xy
set xrange [40:1500]
set yrange [1:5000]
set xlabel 'range R [m]'
set ylabel 'energy at the target T [kJ]'
set grid
set key bottom right box opaque noenhanced
set samples 400
set title "fig:XY: the coordinates (X, Y) of eq:XY_RT about (R0, T0) = (240 m, 26 kJ)\noptimal engines scale along lines of constant X; the dashed lines bound the X each block covers" noenhanced
T_at(R, X) = 26 * (R / 240)**5 * exp(-5.099019514 * X)
set arrow from 73.9909,32.8988 to 778.474,20.5479 lw 2 lc rgb 'black' front
set label 'X' at 778.474,20.5479 offset 0.5,0 front
set arrow from 213.358,14.4363 to 292,69.3161 lw 2 lc rgb 'black' front
set label 'Y' at 292,69.3161 offset 0.5,0 front
set object circle at 240,26 size screen 0.006 fc rgb 'black' fs solid front
plot T_at(x, -0.55) with lines dt 2 lw 2 lc rgb '#1f77b4' title 'θi = 30°, F = 1: X in [-0.55, 0.57]', T_at(x, 0.57) with lines dt 2 lw 2 lc rgb '#1f77b4' notitle, \
     T_at(x, -0.55) with lines dt 3 lw 2 lc rgb '#ff7f0e' title 'θi = 30°, F = 2/3: X in [-0.55, 0.57]', T_at(x, 0.57) with lines dt 3 lw 2 lc rgb '#ff7f0e' notitle, \
     T_at(x, -0.52) with lines dt 4 lw 2 lc rgb '#2ca02c' title 'θi = 40°, F = 2/3: X in [-0.52, 0.52]', T_at(x, 0.52) with lines dt 4 lw 2 lc rgb '#2ca02c' notitle, \
     '-' using 1:2 with points pt 7 ps 1.2 lc rgb 'black' title "the paper's cases", \
     '-' using 1:2:3 with labels left offset 1,0 font ',9' noenhanced notitle
150 40.3
480 124
426 111
250 66
425 224
450 235
450 232
540 700
426 677
407 641
341 540
401 726
482 752
297 858
e
150 40.3 "Alcalá Ca (X -0.55)"
480 124 "Alcalá Ma (480 m and 426 m) (X 0.37)"
250 66 "Alcalá Sa (X -0.14)"
425 224 "tab:Denny, tab:SketchBook-I, tab:Large_Eff (X 0.14)"
540 700 "tab:SketchBook-II rows 1-7 (X 0.15)"
e
