# Fig. 6: RMS of v_A against the number of cells, one panel per shape function, FE and NPC,
# the background shaded by the grid-crossing ratio of paper/08_test_cases.md (light: negligible; middle:
# transition; dark: crossing), the fitted order of each band ± its standard error printed on the panel ('no fit':
# a band with fewer than 3 finished runs). A run the solver stopped is a cross at the top of its panel, labelled.
# LME's panel also holds its runs under the authors' beta (dashed).
# gnuplot -e "data='...'; out='...'; orders='.../dyka_orders.csv'" dyka_fig6.gp
load dir."/common.gp"
w = 12; h = 4.2
sweep = data.'/dyka_sweep.csv'
band1 = 0.1 / (3.298e-5 / (0.5 * 0.1333)); band2 = 1.0 / (3.298e-5 / (0.5 * 0.1333))
top = 0.85
order_of(shape, integrator, band) = system(sprintf("awk -F, '$1==\"%s\" && $2==\"%s\" && $3==\"%s\" {if ($4 != \"nan\" && $4 != \"-nan\") printf \"%%.2f±%%.2g\", $4, $8; else printf \"no fit\"}' %s", shape, integrator, band, orders))
stopped_of(shape) = system(sprintf("awk -F, '$1==\"%s\" && $12==\"failed\" {s = s (s == \"\" ? \"\" : \", \") toupper($2) \" \" $3} END {print s}' %s", shape, sweep))
panel(shape, title) = sprintf("set title '%s'; set object 1 rect from 7,0.04 to band1,1.2 behind fc rgb '#f4f4f4' fs solid noborder; set object 2 rect from band1,0.04 to band2,1.2 behind fc rgb '#dcdcdc' fs solid noborder; set object 3 rect from band2,0.04 to 3600,1.2 behind fc rgb '#b8b8b8' fs solid noborder; set label 1 sprintf('FE  %%s | %%s | %%s', order_of('%s','fe','negligible'), order_of('%s','fe','transition'), order_of('%s','fe','crossing')) at graph 0.03, graph 0.12 tc rgb '#d62728' font ',8'; set label 2 sprintf('NPC %%s | %%s | %%s', order_of('%s','npc','negligible'), order_of('%s','npc','transition'), order_of('%s','npc','crossing')) at graph 0.03, graph 0.05 tc rgb '#1f77b4' font ',8'; set label 3 (stopped_of('%s') eq '' ? '' : 'stopped: '.stopped_of('%s')) at graph 0.97, first top*0.8 right font ',8'; plot sweep using (strcol(1) eq '%s' && strcol(2) eq 'fe' && strcol(12) eq 'ok' ? $3 : NaN):8 with linespoints pt 7 lc rgb '#d62728' title 'FE', sweep using (strcol(1) eq '%s' && strcol(2) eq 'npc' && strcol(12) eq 'ok' ? $3 : NaN):8 with linespoints pt 5 lc rgb '#1f77b4' title 'NPC', sweep using (strcol(1) eq '%s' && strcol(12) eq 'failed' ? $3 : NaN):(top) with points pt 2 ps 2 lw 2 lc rgb 'black' notitle", title, shape, shape, shape, shape, shape, shape, shape, shape, shape, shape, shape)
# The LME panel: the same runs under the authors' beta (dyka_sweep_authors.csv), dashed, open points.
authors = data.'/dyka_sweep_authors.csv'
authors_of(integrator) = sprintf("authors using (strcol(2) eq '%s' && strcol(12) eq 'ok' ? $3 : NaN):8", integrator)
authors_curves = ", ".authors_of('fe')." with linespoints pt 6 dt 2 lc rgb '#d62728' title 'FE, authors'' β', "
authors_curves = authors_curves.authors_of('npc')." with linespoints pt 4 dt 2 lc rgb '#1f77b4' "
authors_curves = authors_curves."title 'NPC, authors'' β', "
authors_curves = authors_curves."authors using (strcol(12) eq 'failed' ? $3 : NaN):(top) with points pt 2 ps 2 lw 2 "
authors_curves = authors_curves."lc rgb 'black' notitle"
# make figures runs the authors' β to 640 cells (every mesh in make studies): the panel's title says where the dashed
# curves end (authors_last, the largest mesh in dyka_sweep_authors.csv).
stats authors using 3 nooutput
authors_last = int(STATS_max)
lme_panel = panel('lme',sprintf('LME, γ = 3 (dashed: the authors’ β, run to %d cells)', authors_last)).authors_curves
draw = "set multiplot layout 1,3 title 'Fig. 6: RMS of v_A (Eq. 43) / |v_0| against the number of cells (CFL 0.5); fitted orders ± s.e. per band: negligible | transition | crossing; ×: run stopped by the solver'; set logscale xy; set xrange [7:3600]; set yrange [0.04:1.2]; set xlabel 'cells'; set ylabel 'RMS / |v_0|'; set key top center; ".panel('linear','linear (Q4)')."; ".panel('ugimp','uGIMP')."; ".lme_panel."; unset multiplot"
load dir."/output.gp"
