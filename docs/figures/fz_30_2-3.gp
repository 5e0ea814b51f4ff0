# Made by figure-fz (tests/bench/figure_fz.cpp) for scripts/figures.sh.
set encoding utf8
set terminal svg size 1200,650 dynamic font 'sans,11'
set output 'docs/figures/fz_30_2-3.svg'
set logscale y
set grid
set samples 60
set xrange [-0.6:0.6]
unset key
set multiplot layout 2,4 title "fig:fZ_vs_X for θi = 30°, F = 2-3: the sweep's optima (points), our fitted f_Z (lines) and the paper's (dashed)\nall over the paper's Z0; X of eq:Xi" noenhanced
set title 'L1' noenhanced
set xlabel 'X'
set ylabel '(L1/L1_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.79151
-0.5 1.72298
-0.45 1.65496
-0.4 1.58816
-0.35 1.5228
-0.3 1.45884
-0.25 1.39654
-0.2 1.33572
-0.15 1.27648
-0.1 1.21892
-0.05 1.16285
0 1.10825
0.05 1.05513
0.1 1.00348
0.15 0.953343
0.2 0.904567
0.25 0.857288
0.3 0.811459
0.35 0.76702
0.4 0.716326
0.45 0.669012
0.5 0.62493
0.55 0.583798
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.1417*exp(-sqrt(26)*0.16124*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.11072*exp(-sqrt(26)*0.179632*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.1128*exp(-sqrt(26)*0.206109*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.23657*exp(-sqrt(26)*0.267664*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.1828*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.192*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L2' noenhanced
set xlabel 'X'
set ylabel '(L2/L2_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.99224
-0.5 1.91386
-0.45 1.82807
-0.4 1.73852
-0.35 1.64755
-0.3 1.55625
-0.25 1.46605
-0.2 1.37747
-0.15 1.2909
-0.1 1.20707
-0.05 1.12606
0 1.04795
0.05 0.973023
0.1 0.901417
0.15 0.833142
0.2 0.768186
0.25 0.706702
0.3 0.648594
0.35 0.593858
0.4 0.534847
0.45 0.480816
0.5 0.43169
0.55 0.387077
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.16351*exp(-sqrt(26)*0.194393*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.05422*exp(-sqrt(26)*0.258605*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.05652*exp(-sqrt(26)*0.318218*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.25811*exp(-sqrt(26)*0.419809*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1.01*exp(-sqrt(26)*0.2626*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.3373*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L4' noenhanced
set xlabel 'X'
set ylabel '(L4/L4_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.7587
-0.5 1.7053
-0.45 1.65173
-0.4 1.59864
-0.35 1.54633
-0.3 1.4946
-0.25 1.44372
-0.2 1.39345
-0.15 1.34377
-0.1 1.29482
-0.05 1.24632
0 1.19824
0.05 1.15051
0.1 1.10326
0.15 1.05637
0.2 1.00976
0.25 0.963637
0.3 0.917931
0.35 0.872587
0.4 0.810663
0.45 0.75333
0.5 0.700286
0.55 0.651132
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.23084*exp(-sqrt(26)*0.127735*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.20114*exp(-sqrt(26)*0.144355*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.20498*exp(-sqrt(26)*0.177452*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.45605*exp(-sqrt(26)*0.287061*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.1672*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.1707*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'D' noenhanced
set xlabel 'X'
set ylabel '(D/D_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 2.40531
-0.5 2.2342
-0.45 2.07213
-0.4 1.9196
-0.35 1.77665
-0.3 1.64289
-0.25 1.51812
-0.2 1.40183
-0.15 1.29354
-0.1 1.19289
-0.05 1.09937
0 1.01251
0.05 0.931916
0.1 0.857196
0.15 0.787962
0.2 0.723826
0.25 0.664494
0.3 0.60962
0.35 0.558906
0.4 0.509741
0.45 0.464749
0.5 0.423661
0.55 0.386132
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.04131*exp(-sqrt(26)*0.299218*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.01416*exp(-sqrt(26)*0.316441*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.01482*exp(-sqrt(26)*0.332944*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.06786*exp(-sqrt(26)*0.362648*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.3171*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.3371*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'M' noenhanced
set xlabel 'X'
set ylabel '(M/M_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 8.47047
-0.5 6.83243
-0.45 5.54099
-0.4 4.51227
-0.35 3.6867
-0.3 3.02127
-0.25 2.48221
-0.2 2.04421
-0.15 1.68747
-0.1 1.39589
-0.05 1.1571
0 0.961221
0.05 0.800149
0.1 0.667388
0.15 0.557819
0.2 0.467211
0.25 0.392104
0.3 0.329762
0.35 0.277908
0.4 0.237054
0.45 0.202687
0.5 0.173635
0.55 0.149024
EOD
plot sample [-0.55:-0.3] '+' using 1:(0.87234*exp(-sqrt(26)*0.808084*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(0.956029*exp(-sqrt(26)*0.748553*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(0.954339*exp(-sqrt(26)*0.69534*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(0.825164*exp(-sqrt(26)*0.610976*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(0.99*exp(-sqrt(26)*0.7432*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.6735*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'm' noenhanced
set xlabel 'X'
set ylabel '(m/m_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 15.9281
-0.5 12.3888
-0.45 9.63575
-0.4 7.49402
-0.35 5.8279
-0.3 4.53185
-0.25 3.5237
-0.2 2.73959
-0.15 2.12976
-0.1 1.6555
-0.05 1.28673
0 1
0.05 0.777086
0.1 0.603798
0.15 0.469096
0.2 0.364406
0.25 0.283047
0.3 0.219826
0.35 0.170706
0.4 0.132555
0.45 0.102909
0.5 0.0798771
0.55 0.0619892
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.00292*exp(-sqrt(26)*0.986021*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.00025*exp(-sqrt(26)*0.98785*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.0004*exp(-sqrt(26)*0.990559*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.00513*exp(-sqrt(26)*0.993319*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.9892*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.9934*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'mb' noenhanced
set xlabel 'X'
set ylabel '(mb/mb_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 10.5793
-0.5 8.77689
-0.45 7.24532
-0.4 5.95856
-0.35 4.88517
-0.3 3.99319
-0.25 3.25615
-0.2 2.64843
-0.15 2.14885
-0.1 1.73978
-0.05 1.40524
0 1.13223
0.05 0.910081
0.1 0.729744
0.15 0.583723
0.2 0.465667
0.25 0.370577
0.3 0.29413
0.35 0.232819
0.4 0.180115
0.45 0.139248
0.5 0.107636
0.55 0.0831759
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.24655*exp(-sqrt(26)*0.764832*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.13893*exp(-sqrt(26)*0.823979*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.14231*exp(-sqrt(26)*0.886175*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.41102*exp(-sqrt(26)*1.00939*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.8297*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.8842*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
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
