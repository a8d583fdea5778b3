# Run time against error, one panel per scene, with the Pareto front
# (nothing both faster and more accurate). Input from mote-bench:
#   dir/pareto.dat        ms psnr label is_llvmpipe   (a block per scene)
#   dir/pareto_front.dat  ms psnr                     (a block per scene)
# Usage: gnuplot -e "dir='out/bench'" tests/bench/pareto.gp
if (!exists("dir")) dir = 'out/bench'
pts = dir.'/pareto.dat'
front = dir.'/pareto_front.dat'
set terminal pngcairo size 1400,1000 font ",9"
set output dir.'/pareto.png'
nblocks = int(system(sprintf("grep -c '^# ' %s", pts)))
set multiplot layout 2,2 title "mote: time per frame against error (PSNR vs the reference; identical plotted at 110 dB); line: Pareto front"
set logscale x
set xlabel "ms per frame (median, one thread; log)"
set ylabel "PSNR dB (higher is better)"
set grid
set key bottom right
do for [i=0:nblocks-1] {
    set title system(sprintf("awk 'BEGIN{b=0} /^# /{if (b==%d) print $2} /^$/{e++; if (e==2){b++; e=0}; next} {e=0}' %s", i, pts))
    plot front index i using 1:2 with steps lw 2 lc rgb "#888888" title "Pareto front", \
         pts index i using 1:($4 == 0 ? $2 : 1/0) with points pt 7 ps 1.3 lc rgb "#1f77b4" title "mote", \
         pts index i using 1:($4 == 1 ? $2 : 1/0) with points pt 5 ps 1.3 lc rgb "#d62728" title "llvmpipe", \
         pts index i using 1:2:3 with labels offset 0.8,0.6 left font ",8" notitle
}
unset multiplot
