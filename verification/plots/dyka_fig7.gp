# Fig. 7: the predictor-corrector against forward Euler (LME γ = 3, 40 cells, CFL 0.5): v_A(t) against the exact
# solution, each curve in the method style of palette.gp (LME's colour, the authors' β in lme_authors' colour; the
# integrator's dash and marker, markers every few samples at intervals that differ per integrator, the Newmark
# average's pentagons drawn larger than FE's circles, on which its curve lies). Top: forward Euler
# (left) and the predictor-corrector (Eq. 32, right) over 200 µs. Below: the jump at 46 µs (left) and the same under
# the authors' β (right, paper/09_choices.md, 'The authors' beta'), each with a difference panel under it: each curve
# minus the one it is compared with. make figures (fair = 0): FE and NPC; difference FE − NPC. make studies (fair = 1,
# out dyka_fig7_fair): also FE damped by the PIC/FLIP blend (top left) and NPC's Newmark average (top right); on the
# jump all five, where the average lies on FE and the blend near NPC (the titles name them), so the difference panels
# draw FE − NPC, average − FE and blend − NPC; under the authors' β the blend is calibrated again.
# Reads dyka_lme_[authors_]<integrator>_40.csv (t, v_A, v_exact; the runs share their sampling to 0.01 %).
# gnuplot -e "dir='...'; data='...'; out='...'[; fair=1]" dyka_fig7.gp
load dir."/common.gp"
w = 13; h = 10.5
if (!exists("fair")) fair = 0
file(beta, i) = data.'/dyka_lme_'.(beta eq 'authors' ? 'authors_' : '').i.'_40.csv'
shape(beta) = beta eq 'authors' ? 'lme_authors' : 'lme'
# Markers every few samples, the interval per integrator (so that markers of curves on one another do not coincide).
every(i, span) = span * (i eq 'fe' ? 5 : i eq 'npc' ? 6 : i eq 'feblend' ? 7 : 8)
# Markers' sizes: the Newmark average's pentagon larger, so that it is not taken for FE's circle.
size(i) = i eq 'npcavg' ? 1.8 : 0.9
exact(beta) = sprintf("'%s' using ($1*1e6):3 with lines %s title 'exact'", file(beta, 'fe'), exact_style)
curve(beta, i, span) = sprintf(", '%s' using ($1*1e6):2 with linespoints %s pi %d ps %g title '%s'", \
  file(beta, i), method_style(shape(beta), i), every(i, span), size(i), integrator_name(i))
# Curve a minus curve b, sample by sample, in a's style.
minus(beta, a, b) = sprintf("'< paste -d, %s %s' using ($1*1e6):($2-$5) with linespoints %s pi %d ps %g title '%s − %s'", \
  file(beta, a), file(beta, b), method_style(shape(beta), a), every(a, 2), size(a), integrator_name(a), integrator_name(b))
zero = sprintf("0 with lines lw 1 lc rgb '%s' notitle", c_context)

# Panels' places (screen fractions): two columns; the top row; the jump above its difference panel.
left_of(c) = c == 1 ? 0.055 : 0.56
right_of(c) = c == 1 ? 0.485 : 0.99
place(c, bottom, top) = sprintf("set lmargin at screen %g; set rmargin at screen %g; set bmargin at screen %g; set tmargin at screen %g; ", \
  left_of(c), right_of(c), bottom, top)

full = "set xlabel 't (µs)'; set ylabel 'v_A (m/s)'; set format x '%g'; set xrange [0:200]; set yrange [-8:9.5]; set key top center horizontal; "
fe_title = fair ? "forward Euler, undamped and damped by the PIC/FLIP blend" : "forward Euler"
npc_title = fair ? "predictor-corrector (Eq. 32) and its Newmark average" : "predictor-corrector (Eq. 32)"
fe_top = place(1, 0.715, 0.905).full."set title '".fe_title."'; plot ".exact('').curve('', 'fe', 8).(fair ? curve('', 'feblend', 8) : '')
npc_top = place(2, 0.715, 0.905).full."set title '".npc_title."'; plot ".exact('').curve('', 'npc', 8).(fair ? curve('', 'npcavg', 8) : '')

# The jump (t = 40-66 µs): v_A above, the differences below.
jump = "set xrange [40:66]; set yrange [-3.6:8.5]; set xlabel ''; set format x ''; set ylabel 'v_A (m/s)'; set key bottom center horizontal maxrows 2; "
on_jump(beta) = exact(beta).curve(beta, 'fe', 1).curve(beta, 'npc', 1).(fair ? curve(beta, 'feblend', 1).curve(beta, 'npcavg', 1) : '')
jump_title(beta) = (beta eq 'authors' ? "the same under the authors' β" : "on the jump at 46 µs"). \
  (fair ? (beta eq 'authors' ? ': the average on FE, the blend (recalibrated) near NPC' : \
                               ': the Newmark average lies on FE, the blend near NPC') : '')
difference = "set xlabel 't (µs)'; set format x '%g'; set ylabel 'difference (m/s)'; set yrange [-2.2:2.9]; unset title; set key top center horizontal; "
differences(beta) = minus(beta, 'fe', 'npc').(fair ? ', '.minus(beta, 'npcavg', 'fe').', '.minus(beta, 'feblend', 'npc') : '').', '.zero
jump_pair(c, beta) = place(c, 0.33, 0.625).jump."set title \"".jump_title(beta)."\"; plot ".on_jump(beta)."; ". \
  place(c, 0.07, 0.33).difference."plot ".differences(beta)

title = "Fig. 7".(fair ? " with the fair variants" : "").": predictor-corrector against forward Euler (LME γ = 3, 40 cells, CFL 0.5); "
title = title."bottom: the jump at 46 µs, right under the authors’ β,\\nwith each curve's difference from the one it is compared with below it"
title = title.(fair ? " (the Newmark average minus FE, the blend minus NPC: small where the curves coincide)" : " (FE − NPC; no two curves coincide)")
draw = "set multiplot title \"".title."\"; ".fe_top."; ".npc_top."; ".jump_pair(1, '')."; ".jump_pair(2, 'authors')."; unset multiplot"
load dir."/output.gp"
