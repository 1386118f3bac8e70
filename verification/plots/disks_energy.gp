# The colliding disks (scenes/colliding_disks.toml): kinetic, strain and total energy against time (the
# predictor-corrector), forward Euler's total beside it (disks_energy_fe.csv, dashed), and the total momentum. Called by verification/disks_figures.sh with data and out set.
load dir."/common.gp"
set key top right
set xlabel "t (s)"
draw = "set multiplot layout 2,1; \
  set ylabel 'energy (J per m of thickness)'; set key right center; \
  plot data.'/disks_energy.csv' using 1:2 with lines lw 1.5 title 'kinetic', \
       '' using 1:3 with lines lw 1.5 title 'strain', \
       '' using 1:4 with lines lw 2 lt 3 title 'total, NPC', \
       data.'/disks_energy_fe.csv' using 1:4 with lines lw 2 lt 3 dt 2 title 'total, FE (same until the disks meet)'; \
  set ylabel 'momentum (kg m/s per m)'; set key top right; \
  plot data.'/disks_energy.csv' using 1:5 with lines lw 1.5 title 'momentum, x', \
       '' using 1:6 with lines lw 1.5 dt 2 title 'momentum, y'; \
  unset multiplot"
w = 7; h = 5.5
load dir."/output.gp"
