# Made by figure-fz (tests/bench/figure_fz.cpp) for scripts/figures.sh.
set encoding utf8
set terminal svg size 1200,650 dynamic font 'sans,11'
set output 'docs/figures/fz_40_2-3.svg'
set logscale y
set grid
set samples 60
set xrange [-0.6:0.6]
unset key
set multiplot layout 2,4 title "fig:fZ_vs_X for θi = 40°, F = 2-3: the sweep's optima (points), our fitted f_Z (lines) and the paper's (dashed)\nall over the paper's Z0; X of eq:Xi" noenhanced
set title 'L1' noenhanced
set xlabel 'X'
set ylabel '(L1/L1_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.76768
-0.5 1.7059
-0.45 1.64092
-0.4 1.57552
-0.35 1.51086
-0.3 1.44711
-0.25 1.38461
-0.2 1.32345
-0.15 1.26381
-0.1 1.20555
-0.05 1.14883
0 1.09352
0.05 1.0396
0.1 0.987215
0.15 0.936263
0.2 0.886844
0.25 0.838852
0.3 0.79242
0.35 0.740724
0.4 0.691617
0.45 0.649545
0.5 0.603057
0.55 0.563152
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.17461*exp(-sqrt(26)*0.145938*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.13187*exp(-sqrt(26)*0.161945*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.1098*exp(-sqrt(26)*0.173152*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.0947*exp(-sqrt(26)*0.187124*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.09698*exp(-sqrt(26)*0.210477*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.18003*exp(-sqrt(26)*0.260856*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.23343*exp(-sqrt(26)*0.279901*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.1829*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1*exp(-sqrt(26)*0.1866*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L2' noenhanced
set xlabel 'X'
set ylabel '(L2/L2_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.97722
-0.5 1.93353
-0.45 1.86004
-0.4 1.77479
-0.35 1.6842
-0.3 1.59121
-0.25 1.4979
-0.2 1.4057
-0.15 1.31552
-0.1 1.2279
-0.05 1.14309
0 1.06156
0.05 0.983436
0.1 0.909007
0.15 0.838099
0.2 0.770982
0.25 0.707535
0.3 0.647885
0.35 0.584686
0.4 0.526088
0.45 0.477713
0.5 0.423933
0.55 0.379738
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.41683*exp(-sqrt(26)*0.119809*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.19078*exp(-sqrt(26)*0.194767*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.1064*exp(-sqrt(26)*0.236396*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.06427*exp(-sqrt(26)*0.275379*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.06782*exp(-sqrt(26)*0.322831*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.19345*exp(-sqrt(26)*0.399966*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.33988*exp(-sqrt(26)*0.450145*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.2686*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1.01*exp(-sqrt(26)*0.3353*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L4' noenhanced
set xlabel 'X'
set ylabel '(L4/L4_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.70281
-0.5 1.66467
-0.45 1.61942
-0.4 1.57172
-0.35 1.52322
-0.3 1.47421
-0.25 1.42509
-0.2 1.37603
-0.15 1.32725
-0.1 1.27851
-0.05 1.23008
0 1.18174
0.05 1.13348
0.1 1.08551
0.15 1.03769
0.2 0.990243
0.25 0.943031
0.3 0.896367
0.35 0.834498
0.4 0.77534
0.45 0.724026
0.5 0.669888
0.55 0.622889
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.29294*exp(-sqrt(26)*0.0984789*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.22966*exp(-sqrt(26)*0.120096*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.20235*exp(-sqrt(26)*0.132873*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.18332*exp(-sqrt(26)*0.149229*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.18703*exp(-sqrt(26)*0.180558*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.37526*exp(-sqrt(26)*0.280091*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.42377*exp(-sqrt(26)*0.295074*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.1598*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1*exp(-sqrt(26)*0.1491*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'D' noenhanced
set xlabel 'X'
set ylabel '(D/D_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 2.40393
-0.5 2.24341
-0.45 2.08463
-0.4 1.93291
-0.35 1.78961
-0.3 1.65497
-0.25 1.52894
-0.2 1.41131
-0.15 1.30174
-0.1 1.1998
-0.05 1.10503
0 1.01705
0.05 0.935427
0.1 0.85981
0.15 0.78974
0.2 0.72492
0.25 0.664965
0.3 0.609593
0.35 0.556291
0.4 0.507289
0.45 0.464178
0.5 0.421522
0.55 0.384101
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.09857*exp(-sqrt(26)*0.279489*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.04933*exp(-sqrt(26)*0.299266*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.02871*exp(-sqrt(26)*0.310511*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.01778*exp(-sqrt(26)*0.321256*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.01874*exp(-sqrt(26)*0.33463*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.05173*exp(-sqrt(26)*0.356846*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.0877*exp(-sqrt(26)*0.371367*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.3189*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1*exp(-sqrt(26)*0.3372*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'M' noenhanced
set xlabel 'X'
set ylabel '(M/M_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 8.59273
-0.5 6.81528
-0.45 5.49067
-0.4 4.45758
-0.35 3.63747
-0.3 2.98023
-0.25 2.44988
-0.2 2.01955
-0.15 1.66898
-0.1 1.3825
-0.05 1.14786
0 0.955065
0.05 0.796341
0.1 0.665316
0.15 0.557055
0.2 0.467331
0.25 0.392872
0.3 0.330915
0.35 0.281783
0.4 0.240689
0.45 0.204623
0.5 0.176701
0.55 0.151834
EOD
plot sample [-0.55:-0.45] '+' using 1:(0.729825*exp(-sqrt(26)*0.878337*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(0.860079*exp(-sqrt(26)*0.807531*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(0.920245*exp(-sqrt(26)*0.76925*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(0.952921*exp(-sqrt(26)*0.734265*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(0.950194*exp(-sqrt(26)*0.69286*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(0.864105*exp(-sqrt(26)*0.627454*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(0.784246*exp(-sqrt(26)*0.585178*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.7384*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(0.99*exp(-sqrt(26)*0.678*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'm' noenhanced
set xlabel 'X'
set ylabel '(m/m_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 15.9733
-0.5 12.4181
-0.45 9.65601
-0.4 7.50855
-0.35 5.83849
-0.3 4.53968
-0.25 3.52956
-0.2 2.74399
-0.15 2.13308
-0.1 1.65803
-0.05 1.28865
0 1.00147
0.05 0.778212
0.1 0.604657
0.15 0.469758
0.2 0.364913
0.25 0.283436
0.3 0.220125
0.35 0.170946
0.4 0.132727
0.45 0.102961
0.5 0.079966
0.55 0.0620543
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.00252*exp(-sqrt(26)*0.987132*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.00361*exp(-sqrt(26)*0.986676*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.00271*exp(-sqrt(26)*0.987195*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.00157*exp(-sqrt(26)*0.988368*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.00175*exp(-sqrt(26)*0.990402*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.00626*exp(-sqrt(26)*0.993367*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.00528*exp(-sqrt(26)*0.993014*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.9896*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1*exp(-sqrt(26)*0.9933*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'mb' noenhanced
set xlabel 'X'
set ylabel '(mb/mb_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 10.3225
-0.5 8.69257
-0.45 7.21989
-0.4 5.95429
-0.35 4.88721
-0.3 3.99523
-0.25 3.25507
-0.2 2.64414
-0.15 2.14214
-0.1 1.73079
-0.05 1.39474
0 1.12099
0.05 0.898553
0.1 0.71848
0.15 0.572892
0.2 0.455646
0.25 0.361381
0.3 0.285889
0.35 0.221694
0.4 0.171463
0.45 0.134361
0.5 0.102413
0.55 0.0790964
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.44839*exp(-sqrt(26)*0.701086*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.24813*exp(-sqrt(26)*0.765282*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.16746*exp(-sqrt(26)*0.803179*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.12396*exp(-sqrt(26)*0.841479*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.12842*exp(-sqrt(26)*0.893201*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.29603*exp(-sqrt(26)*0.989266*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.45496*exp(-sqrt(26)*1.03915*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.8328*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1.01*exp(-sqrt(26)*0.8776*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
unset title
unset xlabel
unset ylabel
unset tics
unset border
unset grid
set key center center box font ',12'
set yrange [1:2]
plot NaN with points pt 7 lc rgb 'black' title 'the sweep’s optima', NaN with lines lw 2 lc rgb '#1f77b4' title 'our f_Z (re-derived)', NaN with lines lw 2 dt 2 lc rgb '#d62728' title 'the paper’s f_Z (tab:CPNC)'
unset multiplot
