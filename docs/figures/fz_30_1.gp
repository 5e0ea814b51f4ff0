# Made by figure-fz (tests/bench/figure_fz.cpp) for scripts/figures.sh.
set encoding utf8
set terminal svg size 1200,650 dynamic font 'sans,11'
set output 'docs/figures/fz_30_1.svg'
set logscale y
set grid
set samples 60
set xrange [-0.6:0.6]
unset key
set multiplot layout 2,4 title "fig:fZ_vs_X for θi = 30°, F = 1: the sweep's optima (points), our fitted f_Z (lines) and the paper's (dashed)\nall over the paper's Z0; X of eq:Xi" noenhanced
set title 'L1' noenhanced
set xlabel 'X'
set ylabel '(L1/L1_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.84157
-0.5 1.76542
-0.45 1.69165
-0.4 1.61952
-0.35 1.54951
-0.3 1.48133
-0.25 1.41521
-0.2 1.35101
-0.15 1.28848
-0.1 1.22772
-0.05 1.16889
0 1.11168
0.05 1.05624
0.1 1.00254
0.15 0.950567
0.2 0.900297
0.25 0.848107
0.3 0.7928
0.35 0.741547
0.4 0.693683
0.45 0.649012
0.5 0.607151
0.55 0.568121
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.14226*exp(-sqrt(26)*0.170711*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.11422*exp(-sqrt(26)*0.18762*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.11456*exp(-sqrt(26)*0.211311*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.18351*exp(-sqrt(26)*0.2618*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.1869*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(0.9967*exp(-sqrt(26)*0.1837*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.12*exp(-sqrt(26)*0.2277*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L2' noenhanced
set xlabel 'X'
set ylabel '(L2/L2_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 2.31518
-0.5 2.18542
-0.45 2.05777
-0.4 1.93246
-0.35 1.81034
-0.3 1.69199
-0.25 1.57784
-0.2 1.468
-0.15 1.36271
-0.1 1.26195
-0.05 1.16618
0 1.07515
0.05 0.98892
0.1 0.907646
0.15 0.831115
0.2 0.759459
0.25 0.687347
0.3 0.615933
0.35 0.551103
0.4 0.4925
0.45 0.439585
0.5 0.391974
0.55 0.349114
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.16607*exp(-sqrt(26)*0.246055*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.08128*exp(-sqrt(26)*0.296448*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.08062*exp(-sqrt(26)*0.349307*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.21273*exp(-sqrt(26)*0.442983*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1.02*exp(-sqrt(26)*0.3003*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(1.0104*exp(-sqrt(26)*0.3571*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.21*exp(-sqrt(26)*0.4084*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L4' noenhanced
set xlabel 'X'
set ylabel '(L4/L4_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.85786
-0.5 1.79438
-0.45 1.73261
-0.4 1.67172
-0.35 1.61208
-0.3 1.55337
-0.25 1.49572
-0.2 1.43908
-0.15 1.38301
-0.1 1.32763
-0.05 1.27317
0 1.21929
0.05 1.16609
0.1 1.11362
0.15 1.06193
0.2 1.01105
0.25 0.95248
0.3 0.885099
0.35 0.823185
0.4 0.765853
0.45 0.712775
0.5 0.663428
0.55 0.617751
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.2546*exp(-sqrt(26)*0.140328*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.22271*exp(-sqrt(26)*0.158193*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.22444*exp(-sqrt(26)*0.191669*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.36467*exp(-sqrt(26)*0.282901*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.1752*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(0.9937*exp(-sqrt(26)*0.1604*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.31*exp(-sqrt(26)*0.2325*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'D' noenhanced
set xlabel 'X'
set ylabel '(D/D_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 2.48798
-0.5 2.30106
-0.45 2.12679
-0.4 1.96426
-0.35 1.81296
-0.3 1.67222
-0.25 1.54147
-0.2 1.42002
-0.15 1.3073
-0.1 1.20271
-0.05 1.10584
0 1.01608
0.05 0.932986
0.1 0.856164
0.15 0.785145
0.2 0.719591
0.25 0.657534
0.3 0.598925
0.35 0.54543
0.4 0.496632
0.45 0.452118
0.5 0.411539
0.55 0.374536
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.03923*exp(-sqrt(26)*0.311693*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.01772*exp(-sqrt(26)*0.325687*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.0176*exp(-sqrt(26)*0.340878*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.05147*exp(-sqrt(26)*0.367931*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.326*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(1.0025*exp(-sqrt(26)*0.3414*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.05*exp(-sqrt(26)*0.35678*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'M' noenhanced
set xlabel 'X'
set ylabel '(M/M_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 7.28045
-0.5 5.97838
-0.45 4.9209
-0.4 4.05993
-0.35 3.35714
-0.3 2.78174
-0.25 2.30968
-0.2 1.92162
-0.15 1.6019
-0.1 1.33814
-0.05 1.11989
0 0.9391
0.05 0.789076
0.1 0.664257
0.15 0.560297
0.2 0.473452
0.25 0.402959
0.3 0.345434
0.35 0.296779
0.4 0.255428
0.45 0.220223
0.5 0.190139
0.55 0.16443
EOD
plot sample [-0.55:-0.3] '+' using 1:(0.873665*exp(-sqrt(26)*0.754664*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(0.934484*exp(-sqrt(26)*0.709854*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(0.935199*exp(-sqrt(26)*0.664898*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(0.846459*exp(-sqrt(26)*0.585756*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(0.98*exp(-sqrt(26)*0.7034*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(0.9893*exp(-sqrt(26)*0.6514*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(0.841*exp(-sqrt(26)*0.6102*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'm' noenhanced
set xlabel 'X'
set ylabel '(m/m_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 15.9763
-0.5 12.4306
-0.45 9.67047
-0.4 7.52255
-0.35 5.85098
-0.3 4.55036
-0.25 3.5384
-0.2 2.75117
-0.15 2.13885
-0.1 1.66261
-0.05 1.29224
0 1.00426
0.05 0.780363
0.1 0.606303
0.15 0.47101
0.2 0.365861
0.25 0.284158
0.3 0.220687
0.35 0.171355
0.4 0.133027
0.45 0.103255
0.5 0.0801357
0.55 0.0621848
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.00834*exp(-sqrt(26)*0.985212*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.00456*exp(-sqrt(26)*0.987737*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.00447*exp(-sqrt(26)*0.990378*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.00846*exp(-sqrt(26)*0.993306*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.9896*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(0.9988*exp(-sqrt(26)*0.9923*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.01*exp(-sqrt(26)*0.9951*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'mb' noenhanced
set xlabel 'X'
set ylabel '(mb/mb_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 12.0005
-0.5 9.80965
-0.45 8.00165
-0.4 6.50952
-0.35 5.28382
-0.3 4.27893
-0.25 3.45789
-0.2 2.78814
-0.15 2.24271
-0.1 1.79965
-0.05 1.4411
0 1.15108
0.05 0.917243
0.1 0.729239
0.15 0.578364
0.2 0.457664
0.25 0.357893
0.3 0.275934
0.35 0.212772
0.4 0.164041
0.45 0.126454
0.5 0.0974554
0.55 0.075104
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.24625*exp(-sqrt(26)*0.808979*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.1578*exp(-sqrt(26)*0.858328*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.15767*exp(-sqrt(26)*0.91431*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.31493*exp(-sqrt(26)*1.02064*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1.01*exp(-sqrt(26)*0.8609*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(1.0023*exp(-sqrt(26)*0.8918*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.25*exp(-sqrt(26)*0.9647*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
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
