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
-0.55 1.84155
-0.5 1.76549
-0.45 1.69156
-0.4 1.61952
-0.35 1.54953
-0.3 1.48141
-0.25 1.4152
-0.2 1.35089
-0.15 1.28837
-0.1 1.22777
-0.05 1.16885
0 1.1117
0.05 1.05631
0.1 1.00254
0.15 0.950546
0.2 0.900278
0.25 0.847606
0.3 0.792782
0.35 0.741405
0.4 0.693683
0.45 0.648998
0.5 0.607121
0.55 0.568085
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.14234*exp(-sqrt(26)*0.170682*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.11421*exp(-sqrt(26)*0.187619*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.11473*exp(-sqrt(26)*0.211686*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.18278*exp(-sqrt(26)*0.261562*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.1869*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(0.9967*exp(-sqrt(26)*0.1837*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.12*exp(-sqrt(26)*0.2277*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L2' noenhanced
set xlabel 'X'
set ylabel '(L2/L2_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 2.31526
-0.5 2.18561
-0.45 2.05768
-0.4 1.93236
-0.35 1.81031
-0.3 1.69207
-0.25 1.57774
-0.2 1.46801
-0.15 1.36254
-0.1 1.26201
-0.05 1.16619
0 1.07509
0.05 0.988996
0.1 0.907655
0.15 0.831111
0.2 0.759426
0.25 0.687535
0.3 0.61587
0.35 0.551094
0.4 0.4925
0.45 0.439505
0.5 0.391951
0.55 0.349097
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.166*exp(-sqrt(26)*0.246084*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.08124*exp(-sqrt(26)*0.296469*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.08057*exp(-sqrt(26)*0.349165*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.21307*exp(-sqrt(26)*0.443131*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1.02*exp(-sqrt(26)*0.3003*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(1.0104*exp(-sqrt(26)*0.3571*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.21*exp(-sqrt(26)*0.4084*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L4' noenhanced
set xlabel 'X'
set ylabel '(L4/L4_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.85787
-0.5 1.79442
-0.45 1.73253
-0.4 1.67169
-0.35 1.61209
-0.3 1.55345
-0.25 1.49571
-0.2 1.43895
-0.15 1.38282
-0.1 1.3277
-0.05 1.27316
0 1.21929
0.05 1.16618
0.1 1.11361
0.15 1.06187
0.2 1.01101
0.25 0.951906
0.3 0.885088
0.35 0.823033
0.4 0.765853
0.45 0.712772
0.5 0.663399
0.55 0.617717
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.25468*exp(-sqrt(26)*0.140302*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.22269*exp(-sqrt(26)*0.158193*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.22461*exp(-sqrt(26)*0.192048*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.36381*exp(-sqrt(26)*0.282655*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.1752*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(0.9937*exp(-sqrt(26)*0.1604*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.31*exp(-sqrt(26)*0.2325*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'D' noenhanced
set xlabel 'X'
set ylabel '(D/D_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 2.488
-0.5 2.30113
-0.45 2.12675
-0.4 1.96424
-0.35 1.81295
-0.3 1.67225
-0.25 1.54144
-0.2 1.42001
-0.15 1.30725
-0.1 1.20273
-0.05 1.10583
0 1.01606
0.05 0.933013
0.1 0.856167
0.15 0.785143
0.2 0.719581
0.25 0.657556
0.3 0.598906
0.35 0.54542
0.4 0.496632
0.45 0.452092
0.5 0.41153
0.55 0.374529
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.03922*exp(-sqrt(26)*0.311698*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.0177*exp(-sqrt(26)*0.325693*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.0176*exp(-sqrt(26)*0.340866*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.05151*exp(-sqrt(26)*0.367955*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.326*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(1.0025*exp(-sqrt(26)*0.3414*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.05*exp(-sqrt(26)*0.35678*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'M' noenhanced
set xlabel 'X'
set ylabel '(M/M_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 7.28018
-0.5 5.97804
-0.45 4.92097
-0.4 4.06013
-0.35 3.35721
-0.3 2.78168
-0.25 2.30978
-0.2 1.92155
-0.15 1.60203
-0.1 1.3381
-0.05 1.11987
0 0.939153
0.05 0.789046
0.1 0.664254
0.15 0.560298
0.2 0.473466
0.25 0.402794
0.3 0.345459
0.35 0.296766
0.4 0.255428
0.45 0.220253
0.5 0.190145
0.55 0.164434
EOD
plot sample [-0.55:-0.3] '+' using 1:(0.873732*exp(-sqrt(26)*0.754626*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(0.934508*exp(-sqrt(26)*0.709836*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(0.935283*exp(-sqrt(26)*0.665136*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(0.846097*exp(-sqrt(26)*0.585559*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(0.98*exp(-sqrt(26)*0.7034*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(0.9893*exp(-sqrt(26)*0.6514*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(0.841*exp(-sqrt(26)*0.6102*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'm' noenhanced
set xlabel 'X'
set ylabel '(m/m_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 15.9764
-0.5 12.4305
-0.45 9.67053
-0.4 7.52254
-0.35 5.85097
-0.3 4.55034
-0.25 3.53841
-0.2 2.75119
-0.15 2.13886
-0.1 1.6626
-0.05 1.29225
0 1.00426
0.05 0.780358
0.1 0.606302
0.15 0.471009
0.2 0.365862
0.25 0.284167
0.3 0.220688
0.35 0.171357
0.4 0.133027
0.45 0.103256
0.5 0.0801361
0.55 0.0621852
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.00833*exp(-sqrt(26)*0.985215*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.00457*exp(-sqrt(26)*0.987737*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.00446*exp(-sqrt(26)*0.990357*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.0085*exp(-sqrt(26)*0.993317*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.9896*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(0.9988*exp(-sqrt(26)*0.9923*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.01*exp(-sqrt(26)*0.9951*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'mb' noenhanced
set xlabel 'X'
set ylabel '(mb/mb_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 12.0007
-0.5 9.81073
-0.45 8.00095
-0.4 6.50931
-0.35 5.28382
-0.3 4.27929
-0.25 3.45769
-0.2 2.78789
-0.15 2.24233
-0.1 1.79978
-0.05 1.44106
0 1.15106
0.05 0.917362
0.1 0.729249
0.15 0.578351
0.2 0.457639
0.25 0.35775
0.3 0.275907
0.35 0.212728
0.4 0.164041
0.45 0.126434
0.5 0.0974463
0.55 0.0750966
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.24629*exp(-sqrt(26)*0.808972*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.15775*exp(-sqrt(26)*0.858342*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.25] '+' using 1:(1.1578*exp(-sqrt(26)*0.914585*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.25:0.55] '+' using 1:(1.31438*exp(-sqrt(26)*1.0205*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1.01*exp(-sqrt(26)*0.8609*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.4] '+' using 1:(1.0023*exp(-sqrt(26)*0.8918*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0.3:0.57] '+' using 1:(1.25*exp(-sqrt(26)*0.9647*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
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
