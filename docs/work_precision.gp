# Charts of docs/work_precision.csv (made by scripts/work-precision.sh): one panel a design,
# stacked, one legend for all, the 1e-8 target and the default setting marked.
set encoding utf8
set datafile separator ","
set terminal svg size 1100,1350 dynamic font "sans,13"
set output "docs/work_precision.svg"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xrange [1e-6:10]
set yrange [1e-14:1]
set ylabel "largest relative error of R, T, ε"
set grid
steppers = "rk2 rk4 rkf45 rkck rk8pd msadams rk1imp rk2imp rk4imp bsimp msbdf"
err(a,b,c) = (a > b ? (a > c ? a : c) : (b > c ? b : c))
lowest(e) = (e > 0 ? e : 1e-14)
designs = "alcala_ca denny_standard large_eff_l17"
title_of(k) = (k == 1 ? "Alcalá Ca (tab:Alcala_la_Vieja): ordinary" : k == 2 ? "Denny's standard engine: not optimal" : "tab:Large_Eff, l = 17: stiff, released at max ε")
set multiplot layout 3,1 margins 0.1,0.97,0.06,0.86 spacing 0,0.07
do for [k=1:3] {
  design = word(designs, k)
  set title title_of(k) font ",14" noenhanced
  if (k == 1) { set key at screen 0.5, screen 0.985 center top horizontal maxrows 3 width -1 samplen 2 } else { unset key }
  if (k == 3) { set xlabel "median wall time per verified shot [s]" } else { unset xlabel }
  plot for [s in steppers] "docs/work_precision.csv" \
         using (strcol(1) eq "shot" && strcol(2) eq design && strcol(3) eq s && strcol(5) ne "" ? $5 : NaN):(lowest(err($6,$7,$8))) \
         with linespoints lw 1.5 title s, \
       1e-8 with lines dt 2 lw 2 lc rgb "black" title "target 1e-8", \
       "docs/work_precision.csv" using (strcol(1) eq "default" && strcol(2) eq design ? $5 : NaN):(lowest(err($6,$7,$8))) \
         with points pt 3 ps 3 lw 3 lc rgb "black" title "default (rk8pd, 1e-11)", \
       "docs/work_precision.csv" using (strcol(1) eq "calculator" && ((design eq "alcala_ca" && strstrt(strcol(2), "alcala")) || (design eq "denny_standard" && strstrt(strcol(2), "denny"))) ? $5 : NaN):(err($6,$7,0)) \
         with points pt 7 ps 1.5 lc rgb "black" title "calculator", \
       "docs/work_precision.csv" using (strcol(1) eq "optimizer" && ((design eq "alcala_ca" && strstrt(strcol(2), "alcala")) || (design eq "denny_standard" && strstrt(strcol(2), "denny"))) ? $5 : NaN):(lowest(err($6,$7,0))) \
         with points pt 5 ps 1.5 lc rgb "red" title "ab-initio optimum"
}
unset multiplot

set output "docs/cost_stiffness.svg"
set terminal svg size 800,450 dynamic font "sans,13"
unset logscale
unset xrange
unset yrange
set format x "%g"
set format y "%g"
set yrange [0:*]
set xlabel "beam ratio l = L1/L2 (the small-l4 shape of tab:Large\\_Eff, default settings)"
set ylabel "median wall time per shot [µs]"
set y2label "integrator steps"
set y2tics
set key default
set key top left box opaque
set title "Cost of a shot against the stiffness l" font ",14"
plot "docs/work_precision.csv" using (strcol(1) eq "stiffness" && $5 > 0 ? real(substr(strcol(2), 3, 10)) : NaN):($5*1e6) with linespoints lw 2 title "time", \
     "docs/work_precision.csv" using (strcol(1) eq "stiffness" && $5 > 0 ? real(substr(strcol(2), 3, 10)) : NaN):10 axes x1y2 with linespoints lw 2 title "steps"
