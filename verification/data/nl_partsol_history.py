"""Particle A's (particle 0, next to the free end) velocity history from GraMS VTK output (mm, mm/s) to SI CSV.
usage: nl_partsol_history.py DIR CELLS FE|PCE END_TIME [PARTICLE (default 0)] > out.csv
GraMS (src/Formulations/Courant.c) takes dt = CFL h / max_p (CEL + v_x) from the velocities before the step.
U_PCE.c writes file k after step k (k = 0, 1, ...): the initial state is prepended; U_FE.c writes file k before
the particles are updated in step k: file 0 is the initial state. Rows stop at the first t >= END_TIME."""
import os, sys
d, cells, integ, end = sys.argv[1], int(sys.argv[2]), sys.argv[3], float(sys.argv[4])
ip = int(sys.argv[5]) if len(sys.argv) > 5 else 0
h, cel, cfl = 133.3 / cells, 5053019.039, 0.5
def state(k):
    try:
        L = open('%s/Resultados/MPM_MPM_VALUES_%d.vtk' % (d, k)).read().split('\n')
    except FileNotFoundError:
        return None
    n = int(L[4].split()[1])
    i = [j for j, l in enumerate(L) if l.startswith('POINTS')][0]
    x = float(L[i + 1 + ip].split()[0])
    j = [j for j, l in enumerate(L) if l.startswith('VECTORS VELOCITY')][0]
    v = [float(l.split()[0]) for l in L[j + 1:j + 1 + n]]
    return x, v
print('t,A.x,A.v_x')
t, k, negative = 0.0, 0, 0
if integ == 'PCE':
    prev = (h / 2, [-5000.0] * (cells // 4) + [0.0] * (cells - cells // 4))  # A: the first, at h/2
    ip0 = 0
else:
    prev = state(0); k = 1; ip0 = ip
print('%.12e,%.9e,%.9e' % (0.0, prev[0] * 1e-3, prev[1][ip0] * 1e-3))
while t < end:
    s = state(k)
    if s is None:
        sys.exit('%s: no file %d before t = %g' % (d, k, end))
    vmax = max(prev[1])
    negative += vmax < 0
    t += cfl * h / (cel if os.environ.get('FIXED') else cel + vmax)  # FIXED=1: a build with dt = CFL h / CEL
    print('%.12e,%.9e,%.9e' % (t, s[0] * 1e-3, s[1][ip] * 1e-3))
    prev, k = s, k + 1
sys.stderr.write('%s: %d steps with every particle moving towards the free end\n' % (d, negative))
