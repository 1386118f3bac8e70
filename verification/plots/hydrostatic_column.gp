# CB-Geo's hydrostatic column (studies/hydrostatic_column.toml: linear shapes, FE with PIC, h = 0.01, 0.005 and
# 0.0025 m, the stress updated first, USF, or last, USL) at 0.2 s, against rho g H and CB-Geo's published values.
# Top, from data/hydrostatic_column_profiles.csv (every particle: case, h, update, y, sigma_yy, exact): (a) sigma_yy
# against the particle's height y beside the hydrostatic stress -rho g (H - y); (b) their difference near the base
# (y < 0.03 m), the one stress of each cell (that of its mid-height) against the straight line. Bottom, from data/hydrostatic_column.csv (written
# by verification/hydrostatic_column.py): (c) the base stress's gap to rho g H against h, ours and CB-Geo's, beside
# the two terms that explain it (the half-cell rho g h/2, and that less the bottom cell's compression); (d) ours
# against CB-Geo and against that explained term, relative, with the hard check's 0.01 %.
# A cell size is a step of the ramp (coarse dark); USF takes FE's dash and marker, USL USL's; bottom, ours in
# linear's colour (method_style), CB-Geo in other_code_style, the explained terms in reference_style.
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
# marker on every fifth row of 10 particles in (a), on every row in (b)); ours in linear's colour, filled markers
# against CB-Geo, open against the explained term.
mesh_style = "lw 1.5 dt dash(key_of(u)) pt marker(key_of(u)) lc rgb ramp(k, 3)"
ours_style = "lw method_lw dt dash(key_of(u)) pt marker(key_of(u)) ps 1.3 lc rgb colour('linear')"
against_style = "lw method_lw dt dash(key_of(u)) pt open(marker(key_of(u))) ps 1.3 lc rgb colour('linear')"
at_base(u) = strcol(3) eq u ? $1 : NaN
stats base using (abs(100 * $7)) nooutput; largest = STATS_max        # the largest |ours - CB-Geo| (%)
stats base using (-$8) nooutput; rho_g_H = STATS_max                   # rho g H (Pa)

fresh = "unset logscale; set xtics autofreq; set ytics autofreq; "   # each panel's axes from the start
profile = fresh."set title '(a) σ_{yy} of every particle at 0.2 s against its height (USF and USL lie on one another)'; \
  set xlabel 'σ_{yy} (Pa)'; set ylabel 'height y (m)'; set xrange [-1850:0]; set yrange [0:0.1]; set key bottom right; \
  plot profiles using (is_case(3, 'usf') ? $6 : NaN):4 with lines ".exact_style." title '−ρ g (H − y)', \
    for [k = 1:3] for [u in updates] profiles using (is_case(k, u) ? $5 : NaN):4 with linespoints ".mesh_style." \
      pi 50 * 2**(k - 1) title mesh_name(k, u)"
difference = "set title '(b) σ_{yy} + ρ g (H − y) near the base: one stress per cell, its mid-height''s'; \
  set xlabel 'σ_{yy} + ρ g (H − y) (Pa)'; set xrange [-100:100]; set yrange [0:0.03]; set key off; \
  plot for [k = 1:3] for [u in updates] profiles using (is_case(k, u) ? $5 - $6 : NaN):4 with linespoints ".mesh_style." pi 10"
gap = fresh.sprintf("set title '(c) the base: gap to ρ g H = %.1f Pa; ours, CB-Geo and the explained term coincide (d)'; ", rho_g_H)."\
  set xlabel 'cell size h (m)'; set ylabel 'σ_{yy,min} + ρ g H (Pa)'; set logscale xy; set xrange [0.002:0.0125]; \
  set yrange [15:120]; set xtics (0.0025, 0.005, 0.01); set ytics (20, 40, 60, 80, 100); set key top left; \
  plot base using (at_base('usf')):($9 - $8) with lines ".reference_style." title 'ρ g h / 2 (the half-cell)', \
    base using (at_base('usf')):($10 - $8) with linespoints ".reference_style." pt 4 ps 1.5 \
      title 'ρ g h / 2 less the bottom cell''s compression', \
    for [u in updates] base using (at_base(u)):($6 - $8) with points ".other_code_style." ps 2.2 \
      title (u eq 'usf' ? 'CB-Geo (published), USF and USL' : ''), \
    for [u in updates] base using (at_base(u)):($5 - $8) with linespoints ".ours_style." title 'ours, '.update_name(u)"
relative = fresh."set title '(d) ours against CB-Geo and against the explained term'; set xlabel 'cell size h (m)'; \
  set ylabel 'relative difference (%)'; set logscale x; set xrange [0.002:0.0125]; set yrange [-0.04:0.015]; \
  set xtics (0.0025, 0.005, 0.01); set key bottom right; \
  plot for [s = -1:1:2] 0.01 * s with lines ".reference_style." title (s < 0 ? 'the check: ± 0.01 %' : ''), \
    for [u in updates] base using (at_base(u)):(100 * $7) with linespoints ".ours_style." \
      title 'ours − CB-Geo, '.update_name(u), \
    for [u in updates] base using (at_base(u)):(100 * ($5 - $10) / abs($10)) with linespoints ".against_style." \
      title 'ours − the half-cell less the compression, '.update_name(u)"
draw = sprintf("set multiplot layout 2,2 title 'CB-Geo''s hydrostatic column (H = 0.1 m, linear shapes, FE with PIC): ours and CB-Geo''s differ by %.4f %% at most, both by about ρ g h / 2 from ρ g H'; ", largest).profile."; ".difference."; ".gap."; ".relative."; unset multiplot"
load dir."/output.gp"
