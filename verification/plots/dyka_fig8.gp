# Fig. 8: sensitivity of LME to gamma (40 cells, CFL 0.5). Left, top: v_A(t) for each gamma (β = γ / h^2, the
# predictor-corrector) against the exact solution, the gammas coloured by ramp(k, n); left, bottom: each gamma minus
# gamma = 5 (where the gammas from 3 up lie on one another above), its largest |difference| in the key. Right, top:
# RMS of v_A against gamma for both integrators in the method style of palette.gp (LME's colour, the integrator's dash
# and filled marker) under this project's β = γ / h^2 and, in the lme_authors colour with the same filled markers
# drawn smaller and thinner on top, under the authors' β = γ / h̄^2 (h̄ the mean distance to the neighbours). Right,
# bottom: the authors' β's RMS over this project's − 1 (%), per integrator; NPC's two coincide (within 1 %) from a
# gamma on, computed from the CSV and named in the title with their largest difference there.
# Reads dyka_gamma_npc_<gamma>.csv (t, v_A, v_exact; the runs share their sampling to 0.01 %) and dyka_gamma.csv
# (gamma, ..., 4 rms_fe_over_v0, 5 rms_npc_over_v0, ..., 7 rms_fe_authors_over_v0, 8 rms_npc_authors_over_v0).
# gnuplot -e "dir='...'; data='...'; out='...'" dyka_fig8.gp
load dir."/common.gp"
w = 12.5; h = 7.2
gammas = "0.8 1 1.5 2 3 4 5"
n = words(gammas)
last = word(gammas, n)
run(g) = sprintf("%s/dyka_gamma_npc_%s.csv", data, g)
pair(k) = sprintf("< paste -d, %s %s", run(word(gammas, k)), run(last))
gamma_k = "lw 1.5 lc rgb ramp(k, n)"
# The largest |v_A(gamma) - v_A(last gamma)| of each gamma, for the key.
largest = ""
do for [k = 1:n - 1] {
  stats pair(k) using (abs($2 - $5)) nooutput
  largest = largest.sprintf(" %.2g", STATS_max)
}
zero = sprintf("0 with lines lw 1 lc rgb '%s' notitle", c_context)

# Panels' places (screen fractions): the time histories on the left, their key right of them; RMS on the right.
place(left, right, bottom, top) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; set tmargin at screen %g; ", \
  left, right, bottom, top)
history = place(0.06, 0.4, 0.42, 0.85)."set title \"v_A(t), LME (β = γ / h^2), predictor-corrector\\nγ = 3-5 lie on one another (below: each minus γ = 5)\"; ". \
  "set xlabel ''; set format x ''; set ylabel 'v_A (m/s)'; set xrange [0:200]; set yrange [-7:8]; ". \
  "set key at screen 0.41, graph 1 left top Left reverse samplen 2; ". \
  "plot '".run(last)."' using ($1*1e6):3 with lines ".exact_style." title 'exact', ". \
  "for [k = 1:n] run(word(gammas, k)) using ($1*1e6):2 with lines ".gamma_k." title 'γ = '.word(gammas, k)
apart = place(0.06, 0.4, 0.1, 0.4)."unset title; set xlabel 't (µs)'; set format x '%g'; ". \
  "set ylabel 'v_A − v_A(γ = ".last.") (m/s)'; set autoscale y; set key at screen 0.41, graph 1 left top Left reverse samplen 2; ". \
  "plot for [k = 1:n - 1] pair(k) using ($1*1e6):($2 - $5) with lines ".gamma_k." title sprintf('γ = %s: |Δ| ≤ %s', word(gammas, k), word(largest, k)), ".zero

gamma_file = data.'/dyka_gamma.csv'
# The authors' β: lme_authors' colour, the integrator's filled marker, smaller and thinner than β = γ / h^2's.
authors(i) = sprintf("lw 1 dt %d pt %d ps 0.7 lc rgb '%s'", dash(i), marker(i), colour('lme_authors'))
# h̄ (h and a combining macron, ended by {} so that enhanced text keeps the two together), the authors' mean
# distance to the neighbours.
hbar = 'h̄{}'
ours_name(i) = 'LME + '.integrator_name(i).', β = γ / h^2 (this project)'
authors_name(i) = 'LME + '.integrator_name(i).', β = γ / '.hbar.'^2 (the authors’)'
# The authors' β's RMS over this project's − 1 in % (columns `a` over `b`), and "L G M": L the largest |difference|,
# G the smallest gamma from which every difference is within 1 % and M the largest there (G and M "-" where the
# difference at the largest gamma is not within 1 %).
apart_pc(a, b) = (column(a) / column(b) - 1) * 100
coincide(a, b) = system(sprintf("awk -F, 'NR > 1 {g[NR] = $1; d[NR] = ($%d / $%d - 1) * 100; n = NR} END {m = 0; l = 0; from = \"-\"; on = 1; for (k = n; k > 1; k--) {a = d[k] < 0 ? -d[k] : d[k]; if (a > l) l = a; if (a > 1) on = 0; if (on) {if (a > m) m = a; from = g[k]}} printf \"%%.2g %%s %%s\", l, from, (from == \"-\" ? \"-\" : sprintf(\"%%.2g\", m))}' %s", a, b, gamma_file))
npc_same = coincide(8, 5)
fe_same = coincide(7, 4)
last_gamma = real(system(sprintf("awk -F, 'END {print $1}' %s", gamma_file)))
# "within M % from γ = G" where the two coincide over two gammas or more, else the largest difference.
same_text(c) = word(c, 2) ne '-' && real(word(c, 2)) < last_gamma ? sprintf('within %s %% from γ = %s', word(c, 3), word(c, 2)) : ''
key_text(c) = sprintf('|Δ| up to %s %%', word(c, 1)).(same_text(c) eq '' ? '' : ', '.same_text(c))
rms = place(0.6, 0.99, 0.42, 0.85).sprintf("set title \"RMS of v_A against γ under both β rules\\nNPC under both β: %s (below)\"; ", same_text(npc_same) eq '' ? 'apart at every γ' : same_text(npc_same)). \
  "set xlabel ''; set format x ''; set ylabel 'RMS / |v_0|'; set xrange [0.5:5.5]; set autoscale y; set key inside top right Left reverse samplen 3; ". \
  "plot gamma_file using 1:4 with linespoints ".method_style('lme', 'fe')." title ours_name('fe'), ". \
  "'' using 1:5 with linespoints ".method_style('lme', 'npc')." title ours_name('npc'), ". \
  "'' using 1:7 with linespoints ".authors('fe')." title authors_name('fe'), ". \
  "'' using 1:8 with linespoints ".authors('npc')." title authors_name('npc')"
ratio = place(0.6, 0.99, 0.1, 0.4)."unset title; set xlabel 'γ'; set format x '%g'; set ylabel 'RMS(authors’ β) / RMS(γ / h^2) − 1 (%)'; ". \
  "set autoscale y; set key inside top right Left reverse samplen 3; ". \
  "plot gamma_file using 1:(apart_pc(7, 4)) with linespoints ".authors('fe')." title 'LME + FE: '.key_text(fe_same), ". \
  "'' using 1:(apart_pc(8, 5)) with linespoints ".authors('npc')." title 'LME + NPC: '.key_text(npc_same), ".zero
draw = "set multiplot title 'Fig. 8: sensitivity of LME to γ (40 cells, CFL 0.5); h: the grid spacing, ".hbar.": the mean distance to the neighbours (the authors’ β)'; ".history."; ".apart."; ".rms."; ".ratio."; unset multiplot"
load dir."/output.gp"
