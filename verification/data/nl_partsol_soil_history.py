"""The soil block's observed particle (the one at (4.5, 9.5) m: particle 49 of nl_partsol_soil_case.py's Solid.msh)
after every step of a GraMS (NL-PartSol 1d5da04) run, from its VTK output (mm, mm/s) to SI CSV: t,top.u_y,top.v_y
(s, m, m/s; u_y = y - 9.5 m from the particle's position, their DISPLACEMENT field is never updated).

usage: nl_partsol_soil_history.py DIR PCE|FE [END_TIME (default 20)] > out.csv

Their VTK files hold no time; t is rebuilt from their step rule (src/Formulations/Courant.c, DeltaT_CFL):
C_j = max_p (CEL + v_pj) per axis j, dt = CFL min_j h / C_j = CFL h / (CEL + max_{p,j} v_pj) (signed velocities,
not |v|), with h = 2000 mm their smallest element edge (GetMinElementSize) and the particle velocities before the
step. U_PCE.c writes file k after step k (k = 0, 1, ...): the initial state (the element centres, v = 0) is
prepended; U_FE.c writes file k before the particles are updated in step k: file 0 is the initial state. Rows stop
at the first t >= END_TIME, or at the last file when the run stopped early (a line on stderr says when)."""
import math, sys
d, integ = sys.argv[1], sys.argv[2]
end = float(sys.argv[3]) if len(sys.argv) > 3 else 20.0
h, cfl, cel = 2000.0, 0.1, math.sqrt(5.0 / 6.0e-9)


def centres():
    """element centres of Solid.msh (GraMS's initial particles, in element order)"""
    L = open(d + '/Solid.msh').read().split('\n')
    c0, c1 = L.index('Coordinates'), L.index('End Coordinates')
    xy = {int(l.split()[0]): (float(l.split()[1]), float(l.split()[2])) for l in L[c0 + 1:c1] if l.strip()}
    e0, e1 = L.index('Elements'), L.index('End Elements')
    out = []
    for l in L[e0 + 1:e1]:
        n = [int(s) for s in l.split()[1:5]]
        out.append((sum(xy[i][0] for i in n) / 4, sum(xy[i][1] for i in n) / 4))
    return out


X = centres()
ip = min(range(len(X)), key=lambda p: (X[p][0] - 4500.0) ** 2 + (X[p][1] - 9500.0) ** 2)
Y0 = X[ip][1]


def state(k):
    """(y of the observed particle, [velocities of every particle, both axes]) of file k, or None"""
    try:
        L = open('%s/Resultados/MPM_MPM_VALUES_%d.vtk' % (d, k)).read().split('\n')
    except FileNotFoundError:
        return None
    n = int(L[4].split()[1])
    i = [j for j, l in enumerate(L) if l.startswith('POINTS')][0]
    y = float(L[i + 1 + ip].split()[1])
    j = [j for j, l in enumerate(L) if l.startswith('VECTORS VELOCITY')][0]
    v = [[float(s) for s in l.split()[:2]] for l in L[j + 1:j + 1 + n]]
    return y, v


if integ == 'PCE':
    prev, k = (Y0, [[0.0, 0.0] for _ in X]), 0
else:
    prev, k = state(0), 1
print('t,top.u_y,top.v_y')
t = 0.0
print('%.12e,%.9e,%.9e' % (t, (prev[0] - Y0) * 1e-3, prev[1][ip][1] * 1e-3))
while t < end:
    s = state(k)
    if s is None:
        sys.stderr.write('%s: no file %d: the run stopped before t = %g; last row t = %.6g s\n' % (d, k, end, t))
        break
    t += cfl * h / (cel + max(max(v) for v in prev[1]))
    print('%.12e,%.9e,%.9e' % (t, (s[0] - Y0) * 1e-3, s[1][ip][1] * 1e-3))
    prev, k = s, k + 1
sys.stderr.write('%s: observed particle %d at (%g, %g) mm\n' % (d, ip, X[ip][0], X[ip][1]))
