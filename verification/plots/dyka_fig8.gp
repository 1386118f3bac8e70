# Fig. 8: sensitivity of LME to gamma (40 cells, CFL 0.5). Left, top: v_A(t) for each gamma (β = γ / h^2, the
# predictor-corrector) against the exact solution, the gammas coloured by ramp(k, n); left, bottom: each gamma minus
# gamma = 5 (where the gammas from 3 up lie on one another above), its largest |difference| in the key. Right: RMS of
# v_A against gamma for both integrators in the method style of palette.gp (LME's colour, the integrator's dash and
# filled marker) under β = γ / h^2 and, in the lme_authors colour with the same filled markers drawn smaller and
# thinner on top, under the authors' β = γ / hbar^2 (NPC's two lie on one another from γ = 3).
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
rms = place(0.62, 0.99, 0.1, 0.85)."set title \"RMS of v_A against γ\\nNPC under both β coincide from γ = 3\"; ". \
  "set xlabel 'γ'; set ylabel 'RMS / |v_0|'; set xrange [0.5:5.5]; set autoscale y; set format x '%g'; set key inside top right; ". \
  "plot gamma_file using 1:4 with linespoints ".method_style('lme', 'fe')." title 'FE, β = γ / h^2', ". \
  "'' using 1:5 with linespoints ".method_style('lme', 'npc')." title 'NPC, β = γ / h^2', ". \
  "'' using 1:7 with linespoints ".authors('fe')." title 'FE, the authors’ β = γ / hbar^2', ". \
  "'' using 1:8 with linespoints ".authors('npc')." title 'NPC, the authors’ β = γ / hbar^2'"
draw = "set multiplot title 'Fig. 8: sensitivity of LME to γ (40 cells, CFL 0.5)'; ".history."; ".apart."; ".rms."; unset multiplot"
load dir."/output.gp"
