# The temporal order alone: every particle's v at the end time against the same method at the finest CFL (16 times
# finer than the finest compared), RMS over the particles / |v0|, against the CFL at fixed h (columns: 40 and 160
# cells), each shape and integrator in its palette style (data/dyka_temporal.csv), with slopes 1/2, 1 and 2 for
# reference (grey, named beside the smallest CFL). The shapes of one integrator lie on each other (the top titles say
# how far apart at most, from the data): the second row draws linear and uGIMP against LME gamma = 3 with the same
# integrator (difference / LME's - 1, in per cent; the
# range padded so that no point sits on the frame). A run that stopped or failed (ending not done) would be drawn on
# the strip above the data, named in the key; the title says when every run completed.
load dir."/common.gp"
w = 13.3; h = 10
f = data.'/dyka_temporal.csv'
shapes = "linear ugimp lme"
stats f using 4 nooutput
finest = STATS_min; coarsest = STATS_max        # the reference CFL, the largest compared
compared = "$4 > finest"
stats f using (@compared ? $6 : NaN) nooutput
lo = STATS_min / 2; hi = STATS_max * 2
stats f using (@compared ? $4 : NaN) nooutput
xlo = STATS_min / 1.3; xhi = STATS_max * 1.3; first = STATS_min   # the smallest CFL compared
stats f using (@compared && strcol(8) ne 'done' ? 1 : 0) nooutput
off = STATS_sum                                  # runs that stopped or failed
done = "strcol(8) eq 'done'"
mine(n, s, i) = $1 == n && strcol(2) eq s && strcol(3) eq i

# The strip's key entries, one per run that did not complete (none when every run completed).
entries = ''
add(n, s, i, cfl, what) = (entries = entries.sprintf(", keyentry with points %s title '%s: %s, %d cells, CFL %g'", what eq 'stopped' ? stopped_style : failed_style, what, method_name(s, i), n, cfl), 1)
if (off > 0) { stats f using (@compared && strcol(8) ne 'done' ? add($1, strcol(2), strcol(3), $4, strcol(8)) : 0) nooutput }

# LME gamma = 3's differences per mesh, integrator and CFL (index k: CFL = coarsest / 2^k), the second row's reference.
k_of(cfl) = int(log(coarsest / cfl) / log(2) + 0.5)
do for [n in "40 160"] { do for [i in "fe npc"] { do for [k = 0:10] {
  stats f using (mine(n + 0, 'lme', i) && @compared && @done && k_of($4) == k ? $6 : 0) nooutput
  eval(sprintf("ref_%s_%s_%d = %s", n, i, k, STATS_max > 0 ? sprintf('%.12g', STATS_max) : 'NaN'))
} } }
ref(n, i, cfl) = value(sprintf("ref_%d_%s_%d", n, i, k_of(cfl)))
# How far the shapes of one integrator lie from each other (the largest |linear or uGIMP / LME - 1|, per cent, over the
# CFLs compared), per mesh and integrator: named in the top row's titles.
do for [n in "40 160"] { do for [i in "fe npc"] {
  stats f using ((strcol(2) eq 'linear' || strcol(2) eq 'ugimp') && $1 == n && strcol(3) eq i && @compared && @done ? abs(100 * ($6 / ref($1, i, $4) - 1)) : NaN) nooutput
  eval(sprintf("apart_%s_%s = %.12g", n, i, STATS_max))
} }
apart(n, i) = value(sprintf("apart_%d_%s", n, i))

MS = "lw method_lw dt dash(i) pt marker(i) lc rgb colour(s)"
# The reference slopes, through fixed values at the smallest CFL compared, named just right of it.
slope(x, p, c) = c * (x / first)**p
slopes = sprintf("slope(x, 0.5, 0.012) with lines %s notitle, slope(x, 1, 0.0025) with lines %s notitle, slope(x, 2, 0.00025) with lines %s notitle", reference_style, reference_style, reference_style)
at = 1.45 * first
slope_labels = sprintf("set label 11 'slope 1/2' at %g, %g left offset 0,0.7; set label 12 'slope 1' at %g, %g left offset 0,0.7; set label 13 'slope 2' at %g, %g left offset 0,-0.8; ", \
  at, slope(at, 0.5, 0.012), at, slope(at, 1, 0.0025), at, slope(at, 2, 0.00025))
strip = off > 0 ? strip_log(lo, hi, 'stopped (×), failed (○)') : unstrip
strip_points(n) = off == 0 ? '' : sprintf(", f using ($1 == %d && @compared && !(@done) ? $4 : NaN):(strip_y_log(lo, hi)) with points %s notitle", n, stopped_style)
panel(n) = sprintf("set title '%d cells: difference against CFL %g;\nthe three shapes of each integrator lie on one another:\nlinear, uGIMP within %.0f %% (FE), %.0f %% (NPC) of LME γ = 3 (below)'; ", n, finest, apart(n, 'fe'), apart(n, 'npc')).strip.slope_labels.\
  sprintf("plot for [i in 'fe npc'] for [s in shapes] f using (mine(%d, s, i) && @compared && @done ? $4 : NaN):6 with linespoints ps 1.1 @MS title method_name(s, i), ", n).slopes.strip_points(n).entries
difference(n) = sprintf("set title '%d cells: linear and uGIMP against LME γ = 3 with the same integrator'; ", n).unstrip."unset label 11; unset label 12; unset label 13; unset logscale y; set yrange [*:*]; set ytics auto; set offsets 0, 0, graph 0.06, graph 0.06; ".\
  sprintf("plot 0 with lines %s notitle, for [i in 'fe npc'] for [s in 'linear ugimp'] f using (mine(%d, s, i) && @compared && @done ? $4 : NaN):(100 * ($6 / ref(%d, i, $4) - 1)) with linespoints ps 1.1 @MS title method_name(s, i)", reference_style, n, n)
title = sprintf("Step refined at fixed h: every particle's v at 200 µs against the same method at CFL %g (RMS over the particles / |v_0|)%s", finest, off == 0 ? '; every run completed' : '')
draw = "set multiplot layout 2,2 title title margins 0.06, 0.76, 0.06, 0.87 spacing 0.07, 0.1; ".\
  sprintf("set logscale x; set xrange [%g:%g]; set xtics (0.0125, 0.025, 0.05, 0.1, 0.2, 0.4); set xlabel 'CFL (dt = CFL h / c)'; ", xlo, xhi).\
  "set key at screen 0.775, graph 0.95 left top Left reverse samplen 2.5; ".\
  sprintf("set logscale y; set yrange [%g:%g]; set ylabel 'difference / |v_0|'; set format y '%%g'; ", lo, hi).\
  "unset key; ".panel(40)."; set key; unset ylabel; ".panel(160)."; ".\
  "unset key; set ylabel 'difference / LME γ = 3''s - 1 (%)'; ".difference(40)."; set key; unset ylabel; ".difference(160)."; unset multiplot"
load dir."/output.gp"
