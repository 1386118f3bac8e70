# The one visual identity of every figure (make figures, make studies, mpm plot): every colour, dash and marker a
# figure draws is defined here and nowhere else (tests/figure_style.py checks it). The rule:
#   - a shape function (and each of today's baselines that is a shape: the B-splines, LME at small gamma) has one
#     colour, colour(SHAPE);
#   - an integrator (FE, NPC, USL, MUSL and the fair variants of Fig. 7) has one dash and one filled marker,
#     dash(INTEGRATOR) and marker(INTEGRATOR); the open marker, open(marker(...)), means 2 particles per cell and
#     nothing else (LME under the authors' beta is a shape of its own, lme_authors, with the filled markers);
#   - a method is its shape's colour with its integrator's dash and marker: method_style(SHAPE, INTEGRATOR);
#   - the exact solution is black and thick (exact_style), a second reference (the finite-strain static column, a
#     theory's slope) grey and dotted (reference_style), another code's run grey and dash-dotted (other_code_style);
#   - a sequence (gamma, meshes, amplitudes) takes its colours from one ramp, ramp(K, N): where gamma is what a figure
#     varies (Figs. 4 and 8, gamma on three meshes), LME's gammas are the ramp, not the colours of lme0.8 and lme1.5,
#     which are LME at small gamma as one of today's baselines beside other methods;
#   - another code's run is grey, dash-dotted, with an asterisk (other_code_style), a marker no integrator has;
#   - a run the solver stopped is a black cross, a run no better than a flat line (failed) a black ring, both on the
#     strip above the data (strip_log, strip_linear in common.gp), never at a height a value could have.
# The keys are the method keys of the data files: linear, ugimp, lme (or lme3: gamma = 3), lme_authors (LME under
# the authors' beta), bspline2, bspline3, lme0.8, lme1.5; fe, npc, usl, musl, feblend (FE + PIC/FLIP blend), npcavg
# (NPC with the Newmark average). An unknown key stops gnuplot (undefined variable), so that no curve is drawn in
# a colour nobody chose.

# Shape functions (colour-blind-safe where they meet: red, green and blue never alone carry a difference; the
# dash and the marker of the integrator always come with them).
colour(s) = s eq 'linear' ? '#d62728' : s eq 'ugimp' ? '#2ca02c' : (s eq 'lme' || s eq 'lme3') ? '#1f77b4' : \
  s eq 'lme_authors' ? '#17becf' : s eq 'bspline2' ? '#ff7f0e' : s eq 'bspline3' ? '#8c564b' : \
  s eq 'lme0.8' ? '#e377c2' : s eq 'lme1.5' ? '#9467bd' : unknown_shape_key
shape_name(s) = s eq 'linear' ? 'linear (Q4)' : s eq 'ugimp' ? 'uGIMP' : (s eq 'lme' || s eq 'lme3') ? 'LME γ = 3' : \
  s eq 'lme_authors' ? 'LME, authors’ β' : s eq 'bspline2' ? 'B-spline 2' : s eq 'bspline3' ? 'B-spline 3' : \
  s eq 'lme0.8' ? 'LME γ = 0.8' : s eq 'lme1.5' ? 'LME γ = 1.5' : unknown_shape_key

# Integrators: dash and filled marker.
dash(i) = i eq 'fe' ? 1 : i eq 'npc' ? 2 : i eq 'usl' ? 4 : i eq 'musl' ? 5 : i eq 'feblend' ? 3 : \
  i eq 'npcavg' ? 6 : unknown_integrator_key
marker(i) = i eq 'fe' ? 7 : i eq 'npc' ? 5 : i eq 'usl' ? 9 : i eq 'musl' ? 11 : i eq 'feblend' ? 13 : \
  i eq 'npcavg' ? 15 : unknown_integrator_key
open(point) = point - 1
integrator_name(i) = i eq 'fe' ? 'FE' : i eq 'npc' ? 'NPC' : i eq 'usl' ? 'USL' : i eq 'musl' ? 'MUSL' : \
  i eq 'feblend' ? 'FE + PIC/FLIP blend' : i eq 'npcavg' ? 'NPC, Newmark average' : unknown_integrator_key
set dashtype 6 (8, 3, 2, 3, 2, 3)

# A method: its shape's colour, its integrator's dash and marker (a string for a plot command).
method_lw = 1.5
method_style(s, i) = sprintf("lw %g dt %d pt %d lc rgb '%s'", method_lw, dash(i), marker(i), colour(s))
# The same without the marker, for `with lines` (gnuplot warns at a pt there).
method_line(s, i) = sprintf("lw %g dt %d lc rgb '%s'", method_lw, dash(i), colour(s))
method_name(s, i) = shape_name(s).' + '.integrator_name(i)

# References.
c_exact = '#000000'
exact_style = "lw 2 dt 1 lc rgb '#000000'"
c_reference = '#7f7f7f'
reference_style = "lw 1.5 dt 3 lc rgb '#7f7f7f'"
other_code_style = "lw 1.5 dt 4 pt 3 lc rgb '#7f7f7f'"
c_context = '#c8c8c8'

# Sequences: one ramp (viridis, its palest end left out so that every step shows on white; the steps spaced so that
# neighbours differ in hue, not only in lightness).
ramp_colours = "#440154 #3b528b #2c728e #21918c #28ae80 #5ec962 #addc30"
ramp(k, n) = word(ramp_colours, n <= 1 ? 1 : 1 + int(0.5 + (k - 1) * (words(ramp_colours) - 1.0) / (n - 1)))

# Outcomes: stopped by the solver, failed (no better than a flat line), on the strip above the data.
stopped_style = "pt 2 ps 1.8 lw 2 lc rgb '#000000'"
failed_style = "pt 6 ps 2.0 lw 1.5 lc rgb '#000000'"
# Annotations, black and larger than any method's marker (the only other open shapes besides 2 ppc): a run on its
# mesh's error-cost front (work-precision chart).
front_style = "pt 4 ps 2.6 lw 1.5 lc rgb '#000000'"
c_strip = '#ececec'

# Backgrounds: the grid-crossing bands of the Dyka bar (negligible, transition, crossing), the grid.
c_band1 = '#f4f4f4'; c_band2 = '#dcdcdc'; c_band3 = '#b8b8b8'
c_grid = '#dddddd'

# Scenes (Fig. 11 and mpm plot): the soil, the load, the mesh, the particles, the rollers.
c_soil = '#f2e6d0'; c_load = '#1f4e9a'; c_mesh = '#9a9a9a'; c_particle = '#5a3d1e'
c_roller_y = '#c0392b'; c_roller_x = '#1f7a3a'

# Colour maps: a signed field about zero (Fig. 4), a compressive stress (Fig. 12).
palette_signed = "set palette defined (-1 '#2166ac', 0 '#ffffff', 1 '#b2182b')"
palette_compression = "set palette defined (0 '#08306b', 0.25 '#2171b5', 0.5 '#6baed6', 0.75 '#c6dbef', 1 '#fff5eb')"
