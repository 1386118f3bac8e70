"""Write a GraMS (NL-PartSol 1d5da04) input for the soil block of scenes/soil_block.toml into DIR, in mm, N/mm^2
(MPa), t/mm^3 and s (as the Dyka input of nl_partsol_case.py; %f in their VTK output then keeps 1e-6 mm and mm/s):
a 10 m x 10 m elastic block (E = 5 MPa, nu = 0, rho = 6000 kg/m^3), plane strain, on a frictionless roller base with
frictionless lateral walls, under gravity -9.81 m/s^2 ramped by Eq. (44) with T = 20 s, CFL 0.1.

usage: nl_partsol_soil_case.py DIR SHAPE(LME|uGIMP|MPMQ4) INTEGRATOR(PCE|FE) [STEPS [AT(start|end) [TIMES.csv]]]
(STEPS 0: the default.) TIMES.csv: the history nl_partsol_soil_history.py made of an earlier run of the same case:
its row k's t is the start of step k, which then replaces k dt0 in CurveGravity.txt (beyond its last row: + dt0
a step). Their step shrinks below dt0 whenever a particle moves up (or along +x), so k dt0 runs ahead of their clock; a second
run on the first's times lands the ramp on their own step times (the histories here: two passes, the second on
the first's times; a third moves top.u_y by under 1e-7 m).

Writes in DIR:
  Box.msh          the background grid, 6 x 6 nodes, 2 m cells (GiD mesh, node ids 1-based, i along x outer)
  Solid.msh        the block's mesh, 10 x 10 elements of 1 m: GraMS puts one particle at each element's centre
                   (x, y = 0.5, ..., 9.5 m, as the scene's 2 x 2 per cell); particle p = 10 i + j sits at
                   (i + 0.5, j + 0.5) m
  Material.txt     the particles of the material (all, 0-based); Gravity.txt the particles gravity acts on (all)
  Bottom.txt, Left.txt, Right.txt   0-based grid node lists at y = 0, x = 0, x = 10 m (rollers: V.y, V.x, V.x = 0)
  CurveZero.txt    a constant zero curve (the rollers' velocity, gravity's b.x)
  CurveGravity.txt b.y per step (their curves are indexed by the step number, src/MPM/compute_ExternalForces.c):
                   entry k = -9810 g(t) / g mm/s^2 of Eq. (44) with t = k dt0 (AT = start, the default: the step's
                   start, as their RAMP_CURVE's Fx[i] = i/Num) or (k + 1) dt0 (AT = end), dt0 = CFL h / CEL, the
                   step their Courant rule takes while no particle moves up (src/Formulations/Courant.c), or
                   the times of TIMES.csv
  ejemplo.gdf      the input: GramsTime Type=INTEGRATOR, CEL = sqrt(E/rho), CFL = 0.1, N = STEPS (default: the
                   steps of dt0 that reach 20 s, plus 20); GramsShapeFun Type=SHAPE (gamma = 3 for LME);
                   GramsOutputs i=1 (every step: nl_partsol_soil_history.py rebuilds t from every step's velocities)
  Resultados/      the output folder
Run in DIR: GraMS -2D -V ejemplo.gdf (then nl_partsol_soil_history.py)."""
import math, os, sys
d, shape, integ = sys.argv[1], sys.argv[2], sys.argv[3]
W = H = 10000.0            # mm
h, cells = 2000.0, 5       # background grid
E, nu, rho = 5.0, 0.0, 6.0e-9   # N/mm^2, -, t/mm^3
g, T, cfl, end = -9810.0, 20.0, 0.1, 20.0   # mm/s^2, s, -, s
cel = math.sqrt(E / rho)   # 28867.51 mm/s
dt0 = cfl * h / cel
steps = int(sys.argv[4]) if len(sys.argv) > 4 and int(sys.argv[4]) > 0 else int(math.ceil(end / dt0)) + 20
at = sys.argv[5] if len(sys.argv) > 5 else 'start'
times = [float(l.split(',')[0]) for l in open(sys.argv[6]).read().split('\n')[1:] if l] if len(sys.argv) > 6 else []
if shape not in ('LME', 'uGIMP', 'MPMQ4') or integ not in ('PCE', 'FE') or at not in ('start', 'end'):
    sys.exit(__doc__)
os.makedirs(d + '/Resultados', exist_ok=True)


def mesh(path, n, size):
    """n x n quadrilaterals of side size on [0, n size]^2; returns {(i, j): node id, 1-based}"""
    ids, lines = {}, ['MESH dimension 3 ElemType Quadrilateral Nnode 4', 'Coordinates']
    for i in range(n + 1):
        for j in range(n + 1):
            ids[(i, j)] = len(ids) + 1
            lines.append('%6d %.10g %.10g 0' % (ids[(i, j)], i * size, j * size))
    lines += ['End Coordinates', '', 'Elements']
    e = 0
    for i in range(n):
        for j in range(n):
            e += 1
            corners = (ids[(i, j + 1)], ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)])
            lines.append('%d %d %d %d %d' % ((e,) + corners))
    lines.append('End Elements')
    open(path, 'w').write('\n'.join(lines) + '\n')
    return ids


box = mesh(d + '/Box.msh', cells, h)
mesh(d + '/Solid.msh', 10, 1000.0)
particles = ''.join('%d\n' % p for p in range(100))
open(d + '/Material.txt', 'w').write(particles)
open(d + '/Gravity.txt', 'w').write(particles)
for name, test in (('Bottom', lambda i, j: j == 0), ('Left', lambda i, j: i == 0), ('Right', lambda i, j: i == cells)):
    open(d + '/%s.txt' % name, 'w').write(''.join('%d\n' % (n - 1) for (i, j), n in sorted(box.items()) if test(i, j)))
num = steps + 10           # their check is TimeStep > Num: keep every read inside the curve
open(d + '/CurveZero.txt', 'w').write('DAT_CURVE NUM#%d\nCONSTANT_CURVE SCALE#0.0\n' % num)


def ramp(t):
    return 1.0 if t > 0.5 * T else 0.5 * (math.sin(2.0 * math.pi * t / T - 0.5 * math.pi) + 1.0)


def start(k):
    """t_k, the start of step k (0-based)"""
    return times[k] if k < len(times) else (times[-1] + (k - len(times) + 1) * dt0 if times else k * dt0)


shift = 0 if at == 'start' else 1
open(d + '/CurveGravity.txt', 'w').write('DAT_CURVE NUM#%d\nCUSTOM_CURVE\n' % num +
                                         ''.join('%.17g\n' % (g * ramp(start(k + shift))) for k in range(num)))
shapefun = 'GramsShapeFun (Type=%s) {\n%s    }' % (shape, '\tgamma=3\n' if shape == 'LME' else '')
open(d + '/ejemplo.gdf', 'w').write('''GramsBox (Type=GID,File=Box.msh) {

    GramsBoundary (File=Bottom.txt) {
	BcDirichlet V.y CurveZero.txt
    }

    GramsBoundary (File=Left.txt) {
	BcDirichlet V.x CurveZero.txt
    }

    GramsBoundary (File=Right.txt) {
	BcDirichlet V.x CurveZero.txt
    }

}

GramsTime (Type=%s) {
    CEL=%.10g
    CFL=%g
    N=%d
}

GramsSolid2D (File=Solid.msh) {

    GramsMaterials (Particles=Material.txt) {
	Type=LE
	rho=%.10g
	E=%.10g
	mu=%.10g
	Id=0
    }

    %s

    GramsBodyForces (Nodes=Gravity.txt) {
	b.x CurveZero.txt
	b.y CurveGravity.txt
    }

}

GramsOutputs (i=1) {
    DIR=Resultados
}
''' % (integ, cel, cfl, steps, rho, E, nu, shapefun))
