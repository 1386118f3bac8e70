"""Write a GraMS (NL-PartSol 1d5da04) input for the Dyka bar on a one-cell-high strip, as its test/Dyka_LME:
mm, N/mm^2, t/mm^3. Background grid Box.msh (margin cells beyond the free end x = 0, rows above and below), the bar's
mesh Solid.msh (one particle per element, at its centre), Material.txt/Init.txt particle lists, RightBoundary.txt the
grid's nodes at x = L (0-based). Run in DIR: GraMS -2D -V ejemplo.gdf (then nl_partsol_history.py).
usage: nl_partsol_case.py DIR CELLS SHAPE(MPMQ4|uGIMP|LME) INTEGRATOR(FE|PCE) STEPS MARGIN ROWS
The histories here used STEPS = 620, 2440, 9730 at 40, 160, 640 cells (more than reach t = 2e-4 s), MARGIN = ROWS = 0
but for nl_partsol_dyka_ugimp_pce_640_margin4_rows1.csv (4 and 1)."""
import os, sys
d, cells, shape, integ = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
steps, margin, rows = int(sys.argv[5]), int(sys.argv[6]), int(sys.argv[7])
L = 133.3
h = L / cells
os.makedirs(d + '/Resultados', exist_ok=True)
def mesh(path, i0, i1, j0, j1):
    """cells i0..i1-1 along x (x = i h), rows j0..j1-1 (y from j h - h/2); returns {(i, j): node id, 1-based}"""
    ids, lines = {}, ['MESH dimension 3 ElemType Quadrilateral Nnode 4', 'Coordinates']
    for i in range(i0, i1 + 1):
        for j in range(j0, j1 + 1):
            ids[(i, j)] = len(ids) + 1
            lines.append('%6d %.10g %.10g 0' % (ids[(i, j)], i * h, j * h - h / 2))
    lines += ['End Coordinates', '', 'Elements']
    e = 0
    for i in range(i0, i1):
        for j in range(j0, j1):
            e += 1
            corners = (ids[(i, j + 1)], ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)])
            lines.append('%d %d %d %d %d' % ((e,) + corners))
    lines.append('End Elements')
    open(path, 'w').write('\n'.join(lines) + '\n')
    return ids
box = mesh(d + '/Box.msh', -margin, cells, -rows, 1 + rows)
mesh(d + '/Solid.msh', 0, cells, 0, 1)
open(d + '/Material.txt', 'w').write(''.join('%d\n' % p for p in range(cells)))
open(d + '/Init.txt', 'w').write(''.join('%d\n' % p for p in range(cells // 4)))
fixed = [n - 1 for (i, j), n in sorted(box.items()) if i == cells]
open(d + '/RightBoundary.txt', 'w').write(''.join('%d\n' % n for n in fixed))
open(d + '/CurveConstat.txt', 'w').write('DAT_CURVE NUM#800000\nCONSTANT_CURVE SCALE#0.0\n')
shapefun = 'GramsShapeFun (Type=%s) {\n%s    }' % (shape, '\tgamma=3\n' if shape == 'LME' else '')
open(d + '/ejemplo.gdf', 'w').write('''GramsBox (Type=GID,File=Box.msh) {
    
    GramsBoundary (File=RightBoundary.txt) { 
	BcDirichlet V.x CurveConstat.txt 
    }
    
}

GramsTime (Type=%s) { 
    CEL=5053019.039
    CFL=0.5
    N=%d 
}

GramsSolid2D (File=Solid.msh) {
    
    GramsMaterials (Particles=Material.txt) { 
	Type=LE
	rho=7.8330E-09 
	E=200E3 
	mu=0.00
	Id=0
    }
    
    %s
    
    GramsInitials (Nodes=Init.txt) { 
    	Value=[-5000.00,0.000000] 
    }
    
}

GramsOutputs (i=1) { 
    DIR=Resultados
}
''' % (integ, steps, shapefun))
