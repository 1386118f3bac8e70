# CB-Geo's hydrostatic column (studies/hydrostatic_column.toml: linear shapes, FE with PIC, h = 0.01, 0.005 and
# 0.0025 m, the stress updated first, USF, or last, USL) at 0.2 s, against rho g H and CB-Geo's published values.
# Top, from data/hydrostatic_column_profiles.csv (every particle: case, h, update, y, sigma_yy, exact): (a) sigma_yy
# against the particle's height y beside the hydrostatic stress -rho g (H - y), and beside it, USF - USL of each
# particle (mPa, a solid line in the cell size's ramp colour; USL lies under USF in (a) and (b)); (b) sigma_yy +
# rho g (H - y) near the base (y < 0.03 m), the one stress of each cell (that of its mid-height) against the straight
# line, USF and USL, with its key. Bottom, from
# data/hydrostatic_column.csv (written by verification/hydrostatic_column.py): (c) the base stress's gap to rho g H
# against h, ours and CB-Geo's (its asterisk, larger than ours' markers, under them), beside the two terms that
# explain it (the half-cell rho g h/2, dotted, and that less the bottom cell's compression, a wide grey line under
# ours: it coincides with ours); (d) ours against CB-Geo and against that explained term, relative, with the hard
# check's 0.01 %, each comparison named by a label with an arrow.
# A cell size is a step of the ramp (coarse dark); USF takes FE's dash and marker, USL USL's; bottom, ours in
# linear's colour (method_style), CB-Geo in other_code_style (its asterisk), the explained terms in the reference's
# grey (reference_style; the compression term wide and solid, no marker).
#   gnuplot -e "dir='verification/plots'; data='results/studies/data'; out='...'" hydrostatic_column.gp
load dir."/common.gp"
set datafile missing NaN   # a row another curve's filter leaves out (NaN) is skipped: each curve's line goes on
w = 12.5; h = 8.6
profiles = data.'/hydrostatic_column_profiles.csv'
base = data.'/hydrostatic_column.csv'
sizes = '0.01 0.005 0.0025'
updates = 'usf usl'
key_of(u) = u eq 'usf' ? 'fe' : u            # USF is forward Euler's own update (key fe); USL has its key
update_name(u) = u eq 'usf' ? 'USF' : u eq 'usl' ? 'USL' : unknown_update
hk(k) = word(sizes, k) + 0
is_case(k, u) = abs($2 - hk(k)) < 1e-9 * hk(k) && strcol(3) eq u
mesh_name(k, u) = sprintf("h = %g m, %s", hk(k), update_name(u))
# Styles inside `plot for [k = 1:3] for [u in updates]`: a mesh's ramp colour with the update's dash and marker (a
# marker on every fifth row of 10 particles in (a), on every row in (b)); ours in linear's colour.
mesh_style = "lw 1.5 dt dash(key_of(u)) pt marker(key_of(u)) lc rgb ramp(k, 3)"
ours_style = "lw method_lw dt dash(key_of(u)) pt marker(key_of(u)) ps 1.3 lc rgb colour('linear')"
at_base(u) = strcol(3) eq u ? $1 : NaN
stats base using (abs(100 * $7)) nooutput; largest = STATS_max        # the largest |ours - CB-Geo| (%)
stats base using (-$8) nooutput; rho_g_H = STATS_max                   # rho g H (Pa)
# (d)'s arrows point at the curves at h = 0.005 m: against the explained term (USF), against CB-Geo (USF, USL)
middle(u) = strcol(3) eq u && abs($1 - 0.005) < 1e-9
stats base using (middle('usf') ? 100 * ($5 - $10) / abs($10) : NaN) nooutput; explained_mid = STATS_max
stats base using (middle('usf') ? 100 * $7 : NaN) nooutput; cbgeo_usf_mid = STATS_max
stats base using (middle('usl') ? 100 * $7 : NaN) nooutput; cbgeo_usl_mid = STATS_max
# USF - USL of each particle (the rows of a case's particles come in the same order for USF and USL): their count
# and first place per cell size, then USF's sigma_yy and y, less USL's sigma_yy
array count[3]; array first[3]
do for [k = 1:3] { stats profiles using (is_case(k, 'usf') ? 1 : 0) nooutput; count[k] = int(STATS_sum)
  first[k] = k == 1 ? 0 : first[k - 1] + count[k - 1] }
particles = first[3] + count[3]
array split[particles]; array height[particles]; array seen[3]
put(k, x, y) = (seen[k] = seen[k] + 1, split[first[k] + seen[k]] = x, height[first[k] + seen[k]] = y, 0)
less(k, x) = (seen[k] = seen[k] + 1, split[first[k] + seen[k]] = split[first[k] + seen[k]] - x, 0)
do for [k = 1:3] { seen[k] = 0; stats profiles using (is_case(k, 'usf') ? put(k, $5, $4) : 0) nooutput
  seen[k] = 0; stats profiles using (is_case(k, 'usl') ? less(k, $5) : 0) nooutput }
split_max = 0; do for [i = 1:particles] { split_max = abs(split[i]) > split_max ? abs(split[i]) : split_max }

fresh = "unset logscale; unset label; unset arrow; set xtics autofreq; set ytics autofreq; set format y '%g'; "
# the top row's places: (a), USF - USL beside it, (b)
place(left, right) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen 0.56; " \
  ."set tmargin at screen 0.87; ", left, right)
profile = fresh.place(0.06, 0.37)."set title \"(a) σ_{yy} of every particle at 0.2 s\\nagainst its height\"; \
  set xlabel 'σ_{yy} (Pa)'; set ylabel 'height y (m)'; set xrange [-1850:0]; set yrange [0:0.1]; set key bottom right; \
  plot profiles using (is_case(3, 'usf') ? $6 : NaN):4 with lines ".exact_style." title '−ρ g (H − y)', \
    for [k = 1:3] for [u in updates] profiles using (is_case(k, u) ? $5 : NaN):4 with linespoints ".mesh_style." \
      pi 50 * 2**(k - 1) title mesh_name(k, u)"
split_panel = fresh.place(0.39, 0.55).sprintf("set title \"USF − USL of every particle,\\nat most %.1f mPa " \
  ."(h: colours of (a))\"; ", 1e3 * split_max)."set xlabel 'σ_{yy,USF} − σ_{yy,USL} (mPa)'; set ylabel ''; set format y ''; set xrange [-1:7]; \
  set xtics 2; set yrange [0:0.1]; set key off; \
  plot 0 with lines lw 1 lc rgb c_exact, for [k = 1:3] [i = 1:count[k]:1] '+' \
    using (1e3 * split[first[k] + int(i)]):(height[first[k] + int(i)]) with lines lw 1.5 lc rgb ramp(k, 3)"
difference = fresh.place(0.62, 0.98)."set title \"(b) σ_{yy} + ρ g (H − y) near the base: one stress per cell, " \
  ."its mid-height's;\\nUSL lies under USF (USF − USL: left of this panel)\"; set xlabel 'σ_{yy} + ρ g (H − y) (Pa)'; set ylabel 'height y (m)'; \
  set xrange [-100:225]; set xtics -100, 50, 100; set yrange [0:0.03]; set key top right samplen 2; \
  plot for [k = 1:3] for [u in updates] profiles using (is_case(k, u) ? $5 - $6 : NaN):4 with linespoints ".mesh_style." pi 10 \
    title mesh_name(k, u)"
unplace = "set lmargin; set rmargin; set bmargin; set tmargin; "
gap = fresh.unplace."set origin 0, 0; set size 0.5, 0.47; ".sprintf("set title '(c) the base: gap to ρ g H = %.1f Pa; ours, CB-Geo and the explained term coincide (d)'; ", rho_g_H)."\
  set xlabel 'cell size h (m)'; set ylabel 'σ_{yy,min} + ρ g H (Pa)'; set logscale xy; set xrange [0.002:0.0125]; \
  set yrange [15:120]; set xtics (0.0025, 0.005, 0.01); set ytics (20, 40, 60, 80, 100); set key bottom right; \
  plot base using (at_base('usf')):($9 - $8) with lines ".reference_style." title 'ρ g h / 2 (the half-cell)', \
    base using (at_base('usf')):($10 - $8) with lines lw 6 lc rgb c_reference \
      title 'ρ g h / 2 less the bottom cell''s compression (wide grey)', \
    for [u in updates] base using (at_base(u)):($6 - $8) with points ".other_code_style." ps 3 \
      title (u eq 'usf' ? 'CB-Geo (published), USF and USL' : ''), \
    for [u in updates] base using (at_base(u)):($5 - $8) with linespoints ".ours_style." title 'ours, '.update_name(u)"
# (d): both comparisons in ours' style, told apart by a label with an arrow each
relative = fresh."set origin 0.5, 0; set size 0.5, 0.47; set title '(d) ours against CB-Geo and against the explained term'; \
  set xlabel 'cell size h (m)'; set ylabel 'relative difference (%)'; set logscale x; set xrange [0.002:0.0125]; \
  set yrange [-0.03:0.015]; set xtics (0.0025, 0.005, 0.01); set key bottom right; \
  set label 1 'ours − (ρ g h / 2 less the compression): USF and USL on one another' at 0.0021, 0.0128 left front; \
  set arrow 1 from 0.0042, 0.0118 to 0.0049, explained_mid + 0.0006 lw 1 lc rgb c_exact front; \
  set label 2 'ours − CB-Geo' at 0.0036, -0.0065 left front; \
  set arrow 2 from 0.0045, -0.0055 to 0.0049, cbgeo_usl_mid - 0.0006 lw 1 lc rgb c_exact front; \
  set arrow 3 from 0.0045, -0.0055 to 0.0049, cbgeo_usf_mid - 0.0006 lw 1 lc rgb c_exact front; \
  plot for [s = -1:1:2] 0.01 * s with lines ".reference_style." title (s < 0 ? 'the check: ± 0.01 %' : ''), \
    for [u in updates] base using (at_base(u)):(100 * $7) with linespoints ".ours_style." \
      title 'ours, '.update_name(u), \
    for [u in updates] base using (at_base(u)):(100 * ($5 - $10) / abs($10)) with linespoints ".ours_style." notitle"
draw = sprintf("set multiplot title 'CB-Geo''s hydrostatic column (H = 0.1 m, linear shapes, FE with PIC): ours and CB-Geo''s differ by %.4f %% at most, both by about ρ g h / 2 from ρ g H'; ", largest).profile."; ".split_panel."; ".difference."; ".gap."; ".relative."; unset multiplot"
load dir."/output.gp"
