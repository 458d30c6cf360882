#!/usr/bin/python3
"""Write the 2D bullet case (dissertation 3.3.2, Fig. 3.12) into directory
D: python3 makeCase.py D [n=80] [tEnd=0.8] [write=0.01] [rhoS=100]
[E=1e6] [nu=0.25] [pC=50] [rhoC=7] [pA=1] [silencer=0] [corner=none]
[gap=0] [substeps=1]

A gun: the barrel is the channel x in [0, 1], y in [0.4, 0.6] (walls:
the breech at x = 0 and the bore, patch 'barrel'; the gun's front face at
x = 1, patch 'face'), opening into the air x in [1, 2.5], y in [0, 1]
(outlets at x = 2.5, y = 0 and y = 1: patch 'open').  n cells per unit
length (square cells; n a multiple of 10: the bore is n/5 cells wide).
The air is at rest at pressure pA (default 1) and the air's temperature
(rho 1.4 pA, sound speed 1); the chamber x < 0.2 holds hot compressed gas
(pC, rhoC: by default 50 and 7, ten times the air's temperature, sound
speed 3.16).  The bullet fills the bore from x = 0.2 to 0.35: density
rhoS (the heavy bullet 100, the light one 40: the dissertation's 1250 and
500 in the ratio 2.5), neoHookean E 1e6 (Table 3.1's), nu 0.25 (strains
of 5e-5 under the chamber pressure), sliding on the bore (MPM slip on
'barrel').  'gap' narrows the bullet by that much on each side (windage;
0: it fills the bore); 'corner' is the gas solver's cornerTreatment;
'substeps' the coupling's solidSubsteps (the most solid substeps in one
gas step; 1: the bullet's elastic waves set the step).

silencer=1 puts Fig. 3.12's silencer on the muzzle: a can x in [1, 1.4],
y in [0.3, 0.7] (patch 'silencer', gas walls; free for the MPM grid:
the bullet flies through the can without touching it),
divided by four baffles of two cells at x = 1.1, 1.2, 1.3 and 1.4 (the
last is the can's end), each with a hole one cell wider than the bore on
each side; the air then lies beyond the can, x in [1.4, 2.9].

The gas region is a grid of rectangles between break lines, each fluid or
solid; blockMesh gets one block per fluid rectangle, and each side of a
fluid rectangle that faces a solid one or the outside is a wall or an
outlet.
"""
import os, sys
a = dict(n=80, tEnd=0.8, write=0.01, rhoS=100.0, E=1.0e6, nu=0.25,
         pC=50.0, rhoC=7.0, pA=1.0, silencer=0, corner='none', gap=0.0,
         substeps=1)
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    if k not in a:
        sys.exit(f'makeCase.py: unknown key {k!r}; allowed: {" ".join(a)}')
    a[k] = type(a[k])(v)
n = int(a['n'])
if n % 10 or n <= 0:
    sys.exit('makeCase.py: n must be a positive multiple of 10, got %d' % n)
if not a['pA'] > 0:
    sys.exit('makeCase.py: pA must be > 0, got %g' % a['pA'])
if a['silencer'] not in (0, 1):
    sys.exit('makeCase.py: silencer must be 0 or 1, got %d' % a['silencer'])
dx = 1.0/n; s = n//10          # cells per 0.1
H = 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
for sub in ('0', 'constant', 'system'):
    os.makedirs(os.path.join(d, sub), exist_ok=True)
def w(path, cls, obj, body):
    with open(os.path.join(d, path), 'w') as f:
        f.write(H % (cls, obj) + body)

# The grid of rectangles, in cells: break lines X, Y and what each
# rectangle [X[i], X[i+1]] x [Y[j], Y[j+1]] is (None: solid, else fluid)
bore = (4*s, 6*s)
if a['silencer']:
    baffles = [(n + k*s - 2, n + k*s) for k in (1, 2, 3, 4)]
    can, hole = (3*s, 7*s), (bore[0] - 1, bore[1] + 1)
    airX0 = n + 4*s
    X = sorted({0, n, airX0, airX0 + 15*s} | {b for bf in baffles for b in bf})
    Y = sorted({0, can[0], hole[0], bore[0], bore[1], hole[1], can[1], n})
else:
    baffles, can, hole, airX0 = [], None, None, n
    X = [0, n, n + 15*s]
    Y = [0, bore[0], bore[1], n]

def fluid(i, j):
    x0, x1, y0, y1 = X[i], X[i + 1], Y[j], Y[j + 1]
    if x1 <= n:                                     # the barrel
        return bore[0] <= y0 and y1 <= bore[1]
    if x0 >= airX0:                                 # the air
        return True
    if not (can[0] <= y0 and y1 <= can[1]):         # outside the can
        return False
    if any(b0 <= x0 and x1 <= b1 for b0, b1 in baffles):
        return hole[0] <= y0 and y1 <= hole[1]      # a baffle's hole
    return True

def patch(i, j, side):
    """The patch of side 'W', 'E', 'S' or 'N' of fluid rectangle (i, j)"""
    x0, x1 = X[i], X[i + 1]
    if x0 >= airX0:
        if side == 'W':
            return 'face'
        return 'open'                               # E, S, N: the outside
    return 'barrel' if x1 <= n else 'silencer'

ni, nj = len(X) - 1, len(Y) - 1
vid = {}
def v(x, y):
    return vid.setdefault((x, y), len(vid))
blocks, faces = [], {}
for i in range(ni):
    for j in range(nj):
        if not fluid(i, j):
            continue
        c = (v(X[i], Y[j]), v(X[i + 1], Y[j]), v(X[i + 1], Y[j + 1]),
             v(X[i], Y[j + 1]))
        blocks.append((c, X[i + 1] - X[i], Y[j + 1] - Y[j]))
        for side, nb, edge in (('W', (i - 1, j), (c[3], c[0])),
                               ('S', (i, j - 1), (c[0], c[1])),
                               ('E', (i + 1, j), (c[1], c[2])),
                               ('N', (i, j + 1), (c[2], c[3]))):
            inside = 0 <= nb[0] < ni and 0 <= nb[1] < nj
            if not (inside and fluid(*nb)):
                faces.setdefault(patch(i, j, side), []).append(edge)
N = len(vid)
pts = sorted(vid, key=vid.get)
verts = '\n'.join(f'    ({x*dx!r} {y*dx!r} 0)' for x, y in pts) + '\n' + \
        '\n'.join(f'    ({x*dx!r} {y*dx!r} {dx!r})' for x, y in pts)
hexes = '\n'.join(
    f'    hex ({c[0]} {c[1]} {c[2]} {c[3]} {c[0] + N} {c[1] + N} {c[2] + N} '
    f'{c[3] + N}) ({nx} {ny} 1) simpleGrading (1 1 1)' for c, nx, ny in blocks)
def faceList(edges):
    return ' '.join(f'({p} {q} {q + N} {p + N})' for p, q in edges)
types = dict(barrel='wall', face='wall', silencer='wall', open='patch')
bnd = '\n'.join(f'    {name} {{ type {types[name]}; faces ({faceList(e)}); }}'
                for name, e in faces.items())
empties = ' '.join([f'({c[0]} {c[3]} {c[2]} {c[1]})' for c, _, _ in blocks]
                   + [f'({c[0] + N} {c[1] + N} {c[2] + N} {c[3] + N})'
                      for c, _, _ in blocks])
w('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices
(
{verts}
);
blocks
(
{hexes}
);
boundary
(
{bnd}
    frontAndBack {{ type empty; faces ({empties}); }}
);
''')
w('system/topoSetDict', 'dictionary', 'topoSetDict', '''
actions
(
    { name chamber; type cellSet; action new; source boxToCell;
      box (-1 0.3 -1) (0.2 0.7 1); }
);
''')
rhoA = 1.4*a['pA']
w('system/setFieldsDict', 'dictionary', 'setFieldsDict', f'''
defaultFieldValues ( volScalarFieldValue p {a["pA"]!r} volScalarFieldValue rho {rhoA!r} );
regions ( cellToCell {{ set chamber; fieldValues ( volScalarFieldValue p {a["pC"]}
    volScalarFieldValue rho {a["rhoC"]} ); }} );
''')
w('system/controlDict', 'dictionary', 'controlDict', f'''
application shockMpmFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime {a["tEnd"]}; deltaT 1e-6; writeControl adjustable;
writeInterval {a["write"]}; purgeWrite 0; writeFormat ascii;
writePrecision 10; writeCompression off; timeFormat general;
timePrecision 6; runTimeModifiable false;
''')
w('system/fvSchemes', 'dictionary', 'fvSchemes', '''
ddtSchemes { default Euler; } gradSchemes { default Gauss linear; }
divSchemes { default none; } laplacianSchemes { default none; }
interpolationSchemes { default linear; } snGradSchemes { default corrected; }
''')
w('system/fvSolution', 'dictionary', 'fvSolution', '\n')
w('system/shockMpmDict', 'dictionary', 'shockMpmDict', f'''
gas {{ stepper semiImplicit; scheme WENO5; timeIntegration RK3; CFL 0.5;
    cornerTreatment {a["corner"]}; }}
boundaries {{ open {{ type outlet; }} }}
coupling {{ order couplingFirst; ghostInit ambient;
    solidSubsteps {int(a["substeps"])}; }}
''')
w('constant/thermophysicalProperties', 'dictionary',
  'thermophysicalProperties', 'gamma 1.4; R 1;\n')
w('constant/mpmProperties', 'dictionary', 'mpmProperties', f'''
kernel bspline2; transfer APIC; CFL 0.5;
materials {{ bullet {{ type neoHookean; rho {a["rhoS"]}; E {a["E"]}; nu {a["nu"]}; }} }}
boundary {{ barrel {{ type slip; }} }}
''')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', f'''
regions ( bullet {{ type box; min (0.2 {0.4 + a["gap"]} -1); max (0.35 {0.6 - a["gap"]} 1);
    material bullet; perCell 2; }} );
''')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{n} {n} {dx!r} {a["rhoS"]!r} {a["pC"]!r} {a["rhoC"]!r} '
            f'{a["pA"]!r} {a["silencer"]}\n')
walls = '|'.join(p for p in ('barrel', 'face', 'silencer') if p in faces)
for name, cls, dim, val in (('p', 'volScalarField', '[1 -1 -2 0 0 0 0]', f'uniform {a["pA"]!r}'),
                             ('rho', 'volScalarField', '[1 -3 0 0 0 0 0]', f'uniform {rhoA!r}'),
                             ('U', 'volVectorField', '[0 1 -1 0 0 0 0]', 'uniform (0 0 0)')):
    wall = 'slip' if name == 'U' else 'zeroGradient'
    w('0/' + name, cls, name, f'dimensions {dim};\ninternalField {val};\n'
      f'boundaryField {{ "{walls}" {{ type {wall}; }} open {{ type zeroGradient; }}'
      ' frontAndBack { type empty; } }\n')
