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
-0.55 1.76769
-0.5 1.7059
-0.45 1.64096
-0.4 1.5755
-0.35 1.51082
-0.3 1.44711
-0.25 1.3846
-0.2 1.32343
-0.15 1.26386
-0.1 1.20556
-0.05 1.1488
0 1.0935
0.05 1.0396
0.1 0.987215
0.15 0.936282
0.2 0.886821
0.25 0.838892
0.3 0.792395
0.35 0.740623
0.4 0.691574
0.45 0.649545
0.5 0.603128
0.55 0.563176
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.17475*exp(-sqrt(26)*0.145894*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.13162*exp(-sqrt(26)*0.162051*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.1098*exp(-sqrt(26)*0.173142*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.09468*exp(-sqrt(26)*0.187153*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.09698*exp(-sqrt(26)*0.210474*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.17982*exp(-sqrt(26)*0.26079*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.23324*exp(-sqrt(26)*0.27982*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.1829*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1*exp(-sqrt(26)*0.1866*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L2' noenhanced
set xlabel 'X'
set ylabel '(L2/L2_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.97702
-0.5 1.9335
-0.45 1.86024
-0.4 1.77475
-0.35 1.68412
-0.3 1.59121
-0.25 1.49795
-0.2 1.40573
-0.15 1.31556
-0.1 1.22778
-0.05 1.14311
0 1.06156
0.05 0.983436
0.1 0.909007
0.15 0.838148
0.2 0.771014
0.25 0.7076
0.3 0.647854
0.35 0.584614
0.4 0.526035
0.45 0.477713
0.5 0.423903
0.55 0.379711
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.4183*exp(-sqrt(26)*0.119402*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.19007*exp(-sqrt(26)*0.195064*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.10655*exp(-sqrt(26)*0.236305*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.06426*exp(-sqrt(26)*0.2754*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.06783*exp(-sqrt(26)*0.32282*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.19322*exp(-sqrt(26)*0.3999*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.34028*exp(-sqrt(26)*0.45028*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.2686*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1.01*exp(-sqrt(26)*0.3353*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'L4' noenhanced
set xlabel 'X'
set ylabel '(L4/L4_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 1.70281
-0.5 1.66465
-0.45 1.6195
-0.4 1.57168
-0.35 1.52313
-0.3 1.47421
-0.25 1.42508
-0.2 1.37601
-0.15 1.32729
-0.1 1.27853
-0.05 1.23004
0 1.18171
0.05 1.13347
0.1 1.08551
0.15 1.0377
0.2 0.990192
0.25 0.943096
0.3 0.896298
0.35 0.834397
0.4 0.7753
0.45 0.724026
0.5 0.669967
0.55 0.622917
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.29326*exp(-sqrt(26)*0.0983875*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.22912*exp(-sqrt(26)*0.120308*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.20242*exp(-sqrt(26)*0.13282*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.18329*exp(-sqrt(26)*0.149263*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.18702*exp(-sqrt(26)*0.180565*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.37486*exp(-sqrt(26)*0.279973*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.42353*exp(-sqrt(26)*0.294988*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.1598*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1*exp(-sqrt(26)*0.1491*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'D' noenhanced
set xlabel 'X'
set ylabel '(D/D_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 2.40387
-0.5 2.2434
-0.45 2.0847
-0.4 1.93289
-0.35 1.78959
-0.3 1.65497
-0.25 1.52895
-0.2 1.41131
-0.15 1.30176
-0.1 1.19977
-0.05 1.10503
0 1.01705
0.05 0.935428
0.1 0.85981
0.15 0.789755
0.2 0.724929
0.25 0.664985
0.3 0.609584
0.35 0.556264
0.4 0.507271
0.45 0.464178
0.5 0.421516
0.55 0.384095
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.09888*exp(-sqrt(26)*0.279378*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.04916*exp(-sqrt(26)*0.299349*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.02875*exp(-sqrt(26)*0.310487*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.01777*exp(-sqrt(26)*0.321264*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.01875*exp(-sqrt(26)*0.334626*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.05166*exp(-sqrt(26)*0.356824*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.08778*exp(-sqrt(26)*0.371402*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.3189*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1*exp(-sqrt(26)*0.3372*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'M' noenhanced
set xlabel 'X'
set ylabel '(M/M_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 8.59357
-0.5 6.81538
-0.45 5.49017
-0.4 4.45767
-0.35 3.63763
-0.3 2.98023
-0.25 2.4498
-0.2 2.0195
-0.15 1.66896
-0.1 1.3826
-0.05 1.14783
0 0.95506
0.05 0.796345
0.1 0.665316
0.15 0.557033
0.2 0.467314
0.25 0.392847
0.3 0.330927
0.35 0.281799
0.4 0.240703
0.45 0.204623
0.5 0.176716
0.55 0.151844
EOD
plot sample [-0.55:-0.45] '+' using 1:(0.729142*exp(-sqrt(26)*0.878707*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(0.860533*exp(-sqrt(26)*0.807268*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(0.920128*exp(-sqrt(26)*0.769339*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(0.952927*exp(-sqrt(26)*0.734256*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(0.950185*exp(-sqrt(26)*0.692866*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(0.864207*exp(-sqrt(26)*0.627496*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(0.784029*exp(-sqrt(26)*0.58505*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.7384*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(0.99*exp(-sqrt(26)*0.678*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'm' noenhanced
set xlabel 'X'
set ylabel '(m/m_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 15.9733
-0.5 12.4181
-0.45 9.65599
-0.4 7.50856
-0.35 5.8385
-0.3 4.53968
-0.25 3.52956
-0.2 2.74399
-0.15 2.13307
-0.1 1.65803
-0.05 1.28865
0 1.00147
0.05 0.778211
0.1 0.604657
0.15 0.469757
0.2 0.364912
0.25 0.283435
0.3 0.220125
0.35 0.170948
0.4 0.132727
0.45 0.102961
0.5 0.0799656
0.55 0.0620543
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.00251*exp(-sqrt(26)*0.987135*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.00362*exp(-sqrt(26)*0.98667*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.00271*exp(-sqrt(26)*0.987195*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.00157*exp(-sqrt(26)*0.988366*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.00175*exp(-sqrt(26)*0.990404*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.00627*exp(-sqrt(26)*0.993368*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.00528*exp(-sqrt(26)*0.993014*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.9896*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1*exp(-sqrt(26)*0.9933*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
set title 'mb' noenhanced
set xlabel 'X'
set ylabel '(mb/mb_0)/(R/R_0)^{n_Z}'
$points << EOD
-0.55 10.3218
-0.5 8.6925
-0.45 7.22061
-0.4 5.95412
-0.35 4.88695
-0.3 3.99523
-0.25 3.25513
-0.2 2.64414
-0.15 2.14229
-0.1 1.73067
-0.05 1.39472
0 1.12098
0.05 0.898559
0.1 0.71848
0.15 0.572928
0.2 0.455649
0.25 0.361422
0.3 0.285872
0.35 0.221644
0.4 0.17144
0.45 0.134361
0.5 0.102421
0.55 0.079096
EOD
plot sample [-0.55:-0.45] '+' using 1:(1.44959*exp(-sqrt(26)*0.700766*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.45:-0.35] '+' using 1:(1.24738*exp(-sqrt(26)*0.765581*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.35:-0.2] '+' using 1:(1.16756*exp(-sqrt(26)*0.80311*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.2:0] '+' using 1:(1.12393*exp(-sqrt(26)*0.841523*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0:0.3] '+' using 1:(1.12843*exp(-sqrt(26)*0.893189*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.3:0.45] '+' using 1:(1.29562*exp(-sqrt(26)*0.989156*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [0.45:0.55] '+' using 1:(1.45503*exp(-sqrt(26)*1.03916*$1)) with lines lw 2 dt 1 lc rgb '#1f77b4' notitle, [-0.52:0] '+' using 1:(1*exp(-sqrt(26)*0.8328*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, [0:0.52] '+' using 1:(1.01*exp(-sqrt(26)*0.8776*$1)) with lines lw 2 dt 2 lc rgb '#d62728' notitle, $points using 1:2 with points pt 7 ps 0.7 lc rgb 'black' notitle
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
