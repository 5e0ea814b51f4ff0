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
-0.55 1.79142
-0.5 1.72293
-0.45 1.65496
-0.4 1.58828
-0.35 1.5228
-0.3 1.45884
-0.25 1.39654
-0.2 1.33582
-0.15 1.27658
-0.1 1.2189
-0.05 1.16284
0 1.10829
0.05 1.05513
0.1 1.00348
0.15 0.953378
0.2 0.904607
0.25 0.857295
0.3 0.811438
0.35 0.766897
0.4 0.716317
0.45 0.669012
0.5 0.624964
0.55 0.583799
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.14182*exp(-sqrt(26)*0.161195*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.11076*exp(-sqrt(26)*0.179627*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.11286*exp(-sqrt(26)*0.20618*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.23611*exp(-sqrt(26)*0.26751*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.1828*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.192*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L2' noenhanced
set xlabel 'X'
set ylabel '(L2/L2_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.99206
-0.5 1.91395
-0.45 1.82807
-0.4 1.73864
-0.35 1.64755
-0.3 1.55628
-0.25 1.46605
-0.2 1.37748
-0.15 1.29101
-0.1 1.20703
-0.05 1.126
0 1.04793
0.05 0.973023
0.1 0.901358
0.15 0.833192
0.2 0.768203
0.25 0.706703
0.3 0.648637
0.35 0.593663
0.4 0.534805
0.45 0.480816
0.5 0.431734
0.55 0.387047
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.16365*exp(-sqrt(26)*0.194342*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.0542*exp(-sqrt(26)*0.258639*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.05656*exp(-sqrt(26)*0.318295*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.25724*exp(-sqrt(26)*0.419541*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1.01*exp(-sqrt(26)*0.2626*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.3373*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L4' noenhanced
set xlabel 'X'
set ylabel '(L4/L4_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.75861
-0.5 1.70523
-0.45 1.65173
-0.4 1.59879
-0.35 1.54633
-0.3 1.49462
-0.25 1.44372
-0.2 1.39356
-0.15 1.34389
-0.1 1.29479
-0.05 1.2463
0 1.19828
0.05 1.15051
0.1 1.10325
0.15 1.05643
0.2 1.00982
0.25 0.963648
0.3 0.917929
0.35 0.872474
0.4 0.810658
0.45 0.75333
0.5 0.700316
0.55 0.651137
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.231*exp(-sqrt(26)*0.127675*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.20116*exp(-sqrt(26)*0.144363*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.20503*exp(-sqrt(26)*0.177502*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.4556*exp(-sqrt(26)*0.286933*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.1672*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.1707*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'D' noenhanced
set xlabel 'X'
set ylabel '(D/D_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 2.40524
-0.5 2.23422
-0.45 2.07213
-0.4 1.91965
-0.35 1.77665
-0.3 1.6429
-0.25 1.51812
-0.2 1.40184
-0.15 1.29357
-0.1 1.19288
-0.05 1.09936
0 1.01251
0.05 0.931916
0.1 0.85718
0.15 0.787977
0.2 0.723832
0.25 0.664495
0.3 0.60963
0.35 0.558844
0.4 0.509728
0.45 0.464749
0.5 0.423675
0.55 0.386123
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.04135*exp(-sqrt(26)*0.299201*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.01416*exp(-sqrt(26)*0.316449*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.01483*exp(-sqrt(26)*0.332974*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.06761*exp(-sqrt(26)*0.362555*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.3171*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.3371*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'M' noenhanced
set xlabel 'X'
set ylabel '(M/M_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 8.47104
-0.5 6.83212
-0.45 5.54099
-0.4 4.51208
-0.35 3.6867
-0.3 3.02122
-0.25 2.48221
-0.2 2.04424
-0.15 1.6874
-0.1 1.39592
-0.05 1.15715
0 0.961253
0.05 0.800149
0.1 0.667427
0.15 0.557795
0.2 0.467208
0.25 0.392105
0.3 0.329741
0.35 0.277966
0.4 0.237068
0.45 0.202687
0.5 0.173624
0.55 0.149034
EOD
plot sample [-0.55:-0.3] '+' using 1:(0.872265*exp(-sqrt(26)*0.80812*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(0.956062*exp(-sqrt(26)*0.74852*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(0.954331*exp(-sqrt(26)*0.695304*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(0.825517*exp(-sqrt(26)*0.61114*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(0.99*exp(-sqrt(26)*0.7432*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.6735*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'm' noenhanced
set xlabel 'X'
set ylabel '(m/m_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 15.9282
-0.5 12.3888
-0.45 9.63575
-0.4 7.49397
-0.35 5.8279
-0.3 4.53185
-0.25 3.5237
-0.2 2.73958
-0.15 2.12975
-0.1 1.65551
-0.05 1.28673
0 1
0.05 0.777086
0.1 0.603797
0.15 0.469095
0.2 0.364405
0.25 0.283047
0.3 0.219827
0.35 0.170709
0.4 0.132555
0.45 0.102909
0.5 0.0798765
0.55 0.0619894
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.00291*exp(-sqrt(26)*0.986025*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.00025*exp(-sqrt(26)*0.987851*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.0004*exp(-sqrt(26)*0.990551*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.00517*exp(-sqrt(26)*0.993335*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.9892*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.9934*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'mb' noenhanced
set xlabel 'X'
set ylabel '(mb/mb_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 10.5781
-0.5 8.77695
-0.45 7.24532
-0.4 5.95929
-0.35 4.88517
-0.3 3.99323
-0.25 3.25615
-0.2 2.64862
-0.15 2.14915
-0.1 1.73972
-0.05 1.40519
0 1.13227
0.05 0.910081
0.1 0.729712
0.15 0.583769
0.2 0.465696
0.25 0.37058
0.3 0.294135
0.35 0.232725
0.4 0.180102
0.45 0.139248
0.5 0.10765
0.55 0.0831715
EOD
plot sample [-0.55:-0.3] '+' using 1:(1.24677*exp(-sqrt(26)*0.764752*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.3:0] '+' using 1:(1.13895*exp(-sqrt(26)*0.823995*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.35] '+' using 1:(1.14241*exp(-sqrt(26)*0.886306*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.35:0.55] '+' using 1:(1.40976*exp(-sqrt(26)*1.00904*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.55:0] '+' using 1:(1*exp(-sqrt(26)*0.8297*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.57] '+' using 1:(1*exp(-sqrt(26)*0.8842*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
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
