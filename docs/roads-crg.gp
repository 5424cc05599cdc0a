# SPDX-License-Identifier: Apache-2.0
# The effective road of a tire over one track of an OpenCRG road against the raw track
# (README, "Roads from other tools"). Data: roads-crg.dat in this directory, written by
# scripts/roads-crg.sh (block 0: the raw track; block 1: h of each model). Draw by hand from
# this directory with:  gnuplot roads-crg.gp   (writes roads-crg.png and roads-crg.svg)
if (!exists("png_out")) png_out = 'roads-crg.png'
if (!exists("svg_out")) svg_out = 'roads-crg.svg'

set encoding utf8
set title "Half-round obstacle of an OpenCRG road (halfround_6in.crg, track v = 0.9 m):\nraw track and effective road h(x), default tire at 17.86 kN" noenhanced
set xlabel "x, m (along the road's reference line)"
set ylabel "height, mm"
set xrange [48.8:51.5]
set yrange [-5:170]
set xtics 0.25
set mxtics 5
set grid xtics ytics lc rgb '#d0d0d0' lw 1 dt 1
set key top left reverse Left box opaque samplen 2.5 spacing 1.15 width 1

# The raw track as a grey area; the models in the colours of every tirenv plot
# (src/study/plot.c): rigid grey dashed, springs blue, ring green dash-dot, cam purple.
set style fill solid 0.35 noborder
set style line 1 lc rgb '#b0b0b0'
set style line 2 lc rgb '#808080' lw 2.0 dt 2   # rigid
set style line 3 lc rgb '#1f5fbf' lw 2.5 dt 1   # springs
set style line 4 lc rgb '#2a9d3a' lw 2.0 dt 4   # ring
set style line 5 lc rgb '#9467bd' lw 2.0 dt 1   # cam

set terminal pngcairo size 960,540 font 'Sans,11' noenhanced
set output png_out
plot 'roads-crg.dat' index 0 using 1:2 with filledcurves y1=0 ls 1 title "raw track (1 cm grid)", \
     '' index 1 using 1:2 with lines ls 2 title "rigid disc", \
     '' index 1 using 1:3 with lines ls 3 title "springs", \
     '' index 1 using 1:4 with lines ls 4 title "ring (reference tire)", \
     '' index 1 using 1:5 with lines ls 5 title "cam (MF-Swift tandem)"

set terminal svg size 960,540 font 'Sans,11' noenhanced background rgb 'white'
set output svg_out
replot
unset output
