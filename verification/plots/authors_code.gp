# The authors' code (NL-PartSol 1d5da04) beside this project on the Dyka bar: particle A's velocity v_A(t) of the
# nine cases of tests/authors_table.sh, one column per method (linear + FE, uGIMP + NPC, LME under the authors' beta +
# NPC; their PCE is our NPC). Rows: the histories at 40 cells and at 640 cells, ours (method_style), theirs
# (other_code_style; at 640 cells uGIMP also on their grid extended by 4 cells beyond the free end and a row above and
# below, in reference_style: grey, dotted, no marker) and the exact solution at A's reference position h/2
# (exact_style); then ours - theirs over v0 = 5 m/s at their sample times on the three meshes (the ramp; against
# uGIMP's extended grid at 640 cells a solid line in reference_style's grey), on a symmetric log axis (linear within
# +-1e-5) so that the methods' differences, 1e-4 to 1, read on one scale, with room above 1 for the key.
# Ours: histories/ours_STEM.csv (t, A.v_x, exact_v_x) and histories/difference_STEM.csv (t, dv_over_v0), written by
# `tests/authors_table.sh MPM --histories DIR` (ours on the grid that matches theirs, the run of the table's
# max |dv|/v0); theirs: theirs/nl_partsol_dyka_STEM.csv (t, A.x, A.v_x). STEM is e.g. linear_fe_40, ugimp_pce_640.
#   gnuplot -e "dir='verification/plots'; data='results/studies/data'; out='...'" authors_code.gp
#   (optional: histories='...' (default data/authors_code), theirs='...' (default verification/data))
load dir."/common.gp"
if (!exists("histories")) histories = data.'/authors_code'
if (!exists("theirs")) theirs = dir.'/../data'
w = 13.3; h = 9.6
shapes = 'linear ugimp lme_authors'; integrators = 'fe npc npc'; stems = 'linear_fe ugimp_pce lme_pce'
meshes = '40 160 640'
ours(m, cells) = sprintf('%s/ours_%s_%s.csv', histories, word(stems, m), cells)
difference(m, cells) = sprintf('%s/difference_%s_%s.csv', histories, word(stems, m), cells)
their(m, cells) = sprintf('%s/nl_partsol_dyka_%s_%s.csv', theirs, word(stems, m), cells)
method(m) = method_name(word(shapes, m), word(integrators, m)).(word(integrators, m) eq 'npc' ? ' (their PCE)' : '')
# the symmetric log axis of the difference: sign(d) log10(1 + |d| / d0), labelled in d
d0 = 1e-5
symlog(d) = d >= 0 ? log10(1 + d / d0) : -log10(1 - d / d0)
decade(d) = abs(d) >= 1 ? '1' : sprintf('10^{%d}', floor(log10(abs(d)) + 0.5))
tic(d) = sprintf('"%s" %.6g', d == 0 ? '0' : (d < 0 ? '−' : '').decade(d), symlog(d))
symlog_tics = 'set ytics ('.tic(-1).', '.tic(-0.1).', '.tic(-0.01).', '.tic(-1e-3).', '.tic(-1e-4).', '.tic(0).', '.tic(1e-4).', '.tic(1e-3).', '.tic(0.01).', '.tic(0.1).', '.tic(1).'); '

every(cells) = int(1.5 * cells)     # a marker every 1.5 cells' worth of steps: about ten on each curve
history(m, cells) = sprintf("set title '%s, %s cells'; set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; \
  set xrange [0:200]; set yrange [-7.5:12.5]; set ytics autofreq; set key top left; \
  plot '%s' using ($1 * 1e6):3 with lines %s title 'exact at X_A = h/2', \
    '%s' using ($1 * 1e6):2 with linespoints %s pi %d title 'ours', \
    '%s' using ($1 * 1e6):3 with linespoints %s pi %d title 'theirs (NL-PartSol)'", \
  method(m), cells, ours(m, cells), exact_style, ours(m, cells), method_style(word(shapes, m), word(integrators, m)), \
  every(cells), their(m, cells), other_code_style, every(cells) + 7).(m == 2 && cells eq '640' ? sprintf(", \
    '%s' using ($1 * 1e6):3 with lines %s title 'theirs, their grid extended'", \
    their(m, '640_margin4_rows1'), reference_style) : '')
gap(m) = sprintf("set title '%s: (ours − theirs) / v_0'; set xlabel 't (µs)'; \
  set ylabel '(v_{ours} − v_{theirs}) / v_0'; set xrange [0:200]; set yrange [%.6g:%.6g]; ", \
  method(m), symlog(-1.5), symlog(3000)).symlog_tics."set key top left horizontal ".(m == 2 ? 'maxrows 2 width -2' : 'maxrows 1 width 0')." samplen 2; \
  plot for [k = 3:1:-1] difference(".m.", word(meshes, k)) using ($1 * 1e6):(symlog($2)) \
    with lines lw 1 lc rgb ramp(k, 3) title word(meshes, k).' cells'".(m == 2 ? sprintf(", \
    '%s' using ($1 * 1e6):(symlog($2)) with lines lw 1.5 lc rgb c_reference \
    title '640, grid extended'", difference(m, '640_margin4_rows1')) : '')
panels = ''
do for [m = 1:3] { panels = panels.history(m, '40').'; ' }
do for [m = 1:3] { panels = panels.history(m, '640').'; ' }
do for [m = 1:3] { panels = panels.gap(m).'; ' }
heading = "The authors'' code (NL-PartSol) and ours on the Dyka bar: particle A''s velocity, ours on their grid; ". \
  "bottom, their difference at their times on a symmetric log axis (linear within ± 10^{-5})"
draw = "set multiplot layout 3,3 title '".heading."'; ".panels."unset multiplot"
load dir."/output.gp"
