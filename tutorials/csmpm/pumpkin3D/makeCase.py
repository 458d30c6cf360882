#!/usr/bin/python3
"""Write the pumpkin explosion (dissertation 3.3.2, Fig. 3.13, Table 3.1)
into directory D: python3 makeCase.py D [n=64] [tEnd=0.1] [write=0.02]
[material=neoHookean] [E=1.5e3] [nu=0.25] [rhoS=10] [yield=600]
[residual=-1] [eta=0] [pIn=300] [rhoIn=30] [lobes=8] [groove=0.1]
[thickness=0.06] [np=1] [substeps=32] [vary=0] [seed=1]

The unit cube, n^3 cells, `open` (outlets) all round, gas rho 1.4, p 1.
A pumpkin centred at (0.5, 0.5, 0.45): an oblate shell (horizontal outer
radius 0.28, vertical 0.8 of it) whose outer surface has 'lobes' ribs
(the radius times 1 + groove cos(lobes phi), fading towards the poles)
over a smooth inner surface 'thickness' below the outer one's mean: the
grooves between the ribs are the thin parts (0.032 against 0.088 at the
ribs by default).  A stem (radius 0.03, 0.06 tall) on top.  Inside, an
ellipsoid of hot compressed gas (rhoIn, pIn) filling 0.85 of the inner
surface.  The patch `open` is an outlet for the particles too: a fragment
reaching it leaves the scene.  The shell and stem's cells hold 2 x 2 x 2
particles each; material neoHookean (Table 3.1's elastic pumpkin, E 1.5e3) or henckyJ2
(its plastic one: E 2e4, yield 600; 'residual' and 'eta' its softening,
by default none).  vary > 0: each particle's mass times 1 + vary xi,
xi uniform in [-1, 1] hashed from seed and its position (mpmSetParticles'
densityVariation, as shellExplosion2D's ring).  The cell sets are computed here (blockMesh numbers the
cells i + n (j + n k)) and written to constant/cellSets (Allrun copies
them to constant/polyMesh/sets after blockMesh) for topoSet
(the shell's cellZone) and setFields (the hot gas).  np > 1 writes a
decomposeParDict for np ranks (simple along x, or 2 x np/2 along x and
y, delta 1e-8: boxes of the lattice).
"""
import math, os, sys
sys.path.insert(0, os.path.join(os.environ['MPMFOAM_DIR'], 'bin', 'tools'))
from csmpmCase import Case, material, parameters
a = parameters(dict(n=64, tEnd=0.1, write=0.02, material='neoHookean',
                    E=1.5e3, nu=0.25, rhoS=10.0, residual=-1.0, eta=0.0,
                    pIn=300.0, rhoIn=30.0, lobes=8, groove=0.1,
                    thickness=0.06, np=1, substeps=32, vary=0.0, seed=1,
                    **{'yield': 600.0}), sys.argv[2:])
d = sys.argv[1]
n = int(a['n']); dx = 1.0/n
case = Case(d, ('0', 'constant/cellSets', 'system'))
w = case.write

# The pumpkin's geometry (cell centres inside it)
cx, cy, cz = 0.5, 0.5, 0.45
R, flat = 0.28, 0.8
stemR, stemH = 0.03, 0.06
def scaled(x, y, z):
    """Radius in the oblate frame, and the ribs' factor at (x, y, z)"""
    X, Y, Z = x - cx, y - cy, (z - cz)/flat
    r = math.sqrt(X*X + Y*Y + Z*Z)
    s2 = (X*X + Y*Y)/(r*r) if r > 0 else 0.0
    return r, 1 + a['groove']*math.cos(a['lobes']*math.atan2(Y, X))*s2
shell, hot = [], []
rIn = R - a['thickness']
for k in range(n):
    z = (k + 0.5)*dx
    for j in range(n):
        y = (j + 0.5)*dx
        for i in range(n):
            x = (i + 0.5)*dx
            c = i + n*(j + n*k)
            r, rib = scaled(x, y, z)
            top = cz + flat*R*(1 - a['groove'])
            inStem = (math.hypot(x - cx, y - cy) <= stemR
                      and top - 2*dx <= z <= top + stemH)
            if (rIn <= r <= R*rib) or (inStem and r >= rIn):
                shell.append(c)
            elif r <= 0.85*rIn:
                hot.append(c)
def cellSet(name, cells):
    w(f'constant/cellSets/{name}', 'cellSet', name,
      f'{len(cells)}\n(\n' + '\n'.join(map(str, cells)) + '\n)\n')
cellSet('pumpkin', shell)
cellSet('hot', hot)

case.unitCube(n)
w('system/topoSetDict', 'dictionary', 'topoSetDict', '''
actions
(
    { name pumpkin; type cellZoneSet; action new; source setToCellZone; set pumpkin; }
);
''')
w('system/setFieldsDict', 'dictionary', 'setFieldsDict', f'''
defaultFieldValues ( volScalarFieldValue p 1 volScalarFieldValue rho 1.4 );
regions ( cellToCell {{ set hot; fieldValues ( volScalarFieldValue p {a["pIn"]}
    volScalarFieldValue rho {a["rhoIn"]} ); }} );
''')
case.common(a['tEnd'], a['write'], 17,
            'order couplingFirst; ghostInit ambient; '
            f'solidSubsteps {a["substeps"]};\n    energyAudit yes;',
            f'pumpkin {{ {material(a)} }}',
            'boundary { open { type outlet; } }\n')
vary = (f' densityVariation {{ amplitude {a["vary"]}; seed {int(a["seed"])}; }}'
        if a['vary'] > 0 else '')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', f'''
regions ( pumpkin {{ type cellZone; zone pumpkin; material pumpkin; perCell 2;{vary} }} );
''')
if a['np'] > 1:
    npr = a['np']
    nxyz = f'{npr} 1 1' if npr <= 2 else f'2 {npr//2} 1'
    w('system/decomposeParDict', 'dictionary', 'decomposeParDict', f'''
numberOfSubdomains {npr};
method simple;
coeffs {{ n ({nxyz}); delta 1e-8; }}
''')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{n} {n} {dx!r}\n')
print(f'pumpkin: {len(shell)} shell cells, {len(hot)} hot gas cells')
