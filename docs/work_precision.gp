# Charts of docs/work_precision.csv (made by scripts/work-precision.sh).
set datafile separator ","
set terminal svg size 1200,420 dynamic font "sans,11"
set output "docs/work_precision.svg"
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "median wall time per verified shot [s]"
set ylabel "max relative error of R, T, eps"
set key outside right top
set grid
set multiplot layout 1,3
steppers = "rk2 rk4 rkf45 rkck rk8pd msadams rk2imp rk4imp bsimp msbdf"
err(a,b,c) = (a > b ? (a > c ? a : c) : (b > c ? b : c))
do for [design in "alcala_ca denny_standard large_eff_l17"] {
  set title design noenhanced
  plot for [s in steppers] "docs/work_precision.csv" \
         using (strcol(1) eq "shot" && strcol(2) eq design && strcol(3) eq s && strcol(5) ne "" ? $5 : NaN):(err($6,$7,$8) > 0 ? err($6,$7,$8) : 1e-13) \
         with linespoints title s, \
       "docs/work_precision.csv" using (strcol(1) eq "calculator" && ((design eq "alcala_ca" && strstrt(strcol(2), "alcala")) || (design eq "denny_standard" && strstrt(strcol(2), "denny"))) ? $5 : NaN):(err($6,$7,0)) \
         with points pt 7 ps 1.5 lc rgb "black" title "calculator", \
       "docs/work_precision.csv" using (strcol(1) eq "optimizer" && ((design eq "alcala_ca" && strstrt(strcol(2), "alcala")) || (design eq "denny_standard" && strstrt(strcol(2), "denny"))) ? $5 : NaN):(err($6,$7,0) > 0 ? err($6,$7,0) : 1e-13) \
         with points pt 5 ps 1.5 lc rgb "red" title "ab-initio optimum"
}
unset multiplot

set output "docs/cost_stiffness.svg"
set terminal svg size 600,400 dynamic font "sans,11"
unset logscale
set logscale y
set format x "%g"
set xlabel "beam ratio l (tab:Large_Eff small-l4 shape, rk8pd default tolerances)"
set ylabel "median wall time per shot [s]"
set y2label "integrator steps"
set y2tics
unset title
plot "docs/work_precision.csv" using (strcol(1) eq "stiffness" && $5 > 0 ? real(substr(strcol(2), 3, 10)) : NaN):5 with linespoints title "time", \
     "docs/work_precision.csv" using (strcol(1) eq "stiffness" && $5 > 0 ? real(substr(strcol(2), 3, 10)) : NaN):10 axes x1y2 with linespoints title "steps"
