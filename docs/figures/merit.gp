# Made by figure-merit (tests/bench/figure_merit.cpp) for scripts/figures.sh.
set encoding utf8
set terminal svg size 1100,750 dynamic font 'sans,12'
set output 'docs/figures/merit.svg'
set grid
unset key
set multiplot layout 2,3 title "fig:Merit_Ms: Q/Q_max of 10^3 designs fitted to (240 m, 26 kJ), θi = 30°, F = 1\nupper: a narrow box about the optimum; lower: a wide one. The axis of largest curvature is 11.9° from l_4" noenhanced
set xtics norotate
set xlabel 'l = L_1/L_2'
set ylabel 'Q/Q_{max} [%]'
plot 'docs/figures/merit_narrow.dat' using 1:4 with points pt 7 ps 0.3 lc rgb '#1f5fbf'
set xtics norotate
set xlabel 'l_4 = L_4/L_1'
set ylabel 'Q/Q_{max} [%]'
plot 'docs/figures/merit_narrow.dat' using 2:4 with points pt 7 ps 0.3 lc rgb '#1f5fbf'
set xtics rotate by -30
set xlabel 'μ_b = m_b/M'
set ylabel 'Q/Q_{max} [%]'
plot 'docs/figures/merit_narrow.dat' using 3:4 with points pt 7 ps 0.3 lc rgb '#1f5fbf'
set xtics norotate
set xlabel 'l = L_1/L_2'
set ylabel 'Q/Q_{max} [%]'
plot 'docs/figures/merit_wide.dat' using 1:4 with points pt 7 ps 0.3 lc rgb '#1f5fbf'
set xtics norotate
set xlabel 'l_4 = L_4/L_1'
set ylabel 'Q/Q_{max} [%]'
plot 'docs/figures/merit_wide.dat' using 2:4 with points pt 7 ps 0.3 lc rgb '#1f5fbf'
set xtics rotate by -30
set xlabel 'μ_b = m_b/M'
set ylabel 'Q/Q_{max} [%]'
plot 'docs/figures/merit_wide.dat' using 3:4 with points pt 7 ps 0.3 lc rgb '#1f5fbf'
unset multiplot
