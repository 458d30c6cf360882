#!/usr/bin/python3
"""Write the blast-on-an-ellipse case (dissertation Fig. 3.4: the order of
the coupled solve and the MPM grid update) into directory D:
python3 makeCase.py D [n=128] [tEnd=0.12] [order=couplingFirst] [E=1e5]

The unit square, walls; gas rho 1, p 1 at rest, a blast of p 100 in a
circle of radius 0.06 at (0.25, 0.5).  An ellipse of semi-axes 0.15 and
0.06 centred at (0.55, 0.5), tilted 30 degrees, its upper half dense (rho
50) and its lower half light (rho 5): a biased mass centre, so the blast
pushes and spins it.  Stiff (neoHookean, E 1e5, nu 0.3).  The ellipse's
cells are picked by a field written here (fieldToCell), two cellZones.
"""
import math, os, sys
a = dict(n=128, tEnd=0.12, write=0.01, order='couplingFirst', E=1.0e5)
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    a[k] = type(a[k])(v)
n = int(a['n']); dx = 1.0/n
H = 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
for sub in ('0', 'constant', 'system'):
    os.makedirs(os.path.join(d, sub), exist_ok=True)
def w(path, cls, obj, body):
    with open(os.path.join(d, path), 'w') as f:
        f.write(H % (cls, obj) + body)
w('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 {dx}) (1 0 {dx}) (1 1 {dx}) (0 1 {dx}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({n} {n} 1) simpleGrading (1 1 1) );
boundary
(
    walls {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
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
gas {{ stepper semiImplicit; scheme WENO5; timeIntegration RK3; CFL 0.5; }}
boundaries {{ }}
coupling {{ order {a["order"]}; ghostInit ambient; }}
''')
w('constant/thermophysicalProperties', 'dictionary',
  'thermophysicalProperties', 'gamma 1.4; R 1;\n')
w('constant/mpmProperties', 'dictionary', 'mpmProperties', f'''
kernel bspline2; transfer APIC; CFL 0.5;
materials
{{
    heavy {{ type neoHookean; rho 50; E {a["E"]}; nu 0.3; }}
    light {{ type neoHookean; rho 5; E {a["E"]}; nu 0.3; }}
}}
''')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', '''
regions
(
    heavy { type cellZone; zone heavy; material heavy; perCell 2; }
    light { type cellZone; zone light; material light; perCell 2; }
);
''')
w('system/topoSetDict', 'dictionary', 'topoSetDict', '''
actions
(
    { name heavy; type cellSet; action new; source fieldToCell; field ellipse; min 1.5; max 2.5; }
    { name heavy; type cellZoneSet; action new; source setToCellZone; set heavy; }
    { name light; type cellSet; action new; source fieldToCell; field ellipse; min 0.5; max 1.5; }
    { name light; type cellZoneSet; action new; source setToCellZone; set light; }
);
''')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{n}\n')
c, s_ = math.cos(math.radians(30)), math.sin(math.radians(30))
ell, pv = [], []
for j in range(n):
    for i in range(n):
        x, y = (i + 0.5)*dx - 0.55, (j + 0.5)*dx - 0.5
        u, v = c*x + s_*y, -s_*x + c*y
        inside = (u/0.15)**2 + (v/0.06)**2 <= 1
        ell.append('0' if not inside else ('2' if v > 0 else '1'))
        X, Y = (i + 0.5)*dx, (j + 0.5)*dx
        pv.append('100' if (X - 0.25)**2 + (Y - 0.5)**2 < 0.06**2 else '1')
def field(name, dim, vals, bc='zeroGradient'):
    w('0/' + name, 'volScalarField', name, f'dimensions {dim};\n'
      f'internalField nonuniform List<scalar> {len(vals)}\n(\n' + '\n'.join(vals)
      + f'\n);\nboundaryField {{ walls {{ type {bc}; }} frontAndBack {{ type empty; }} }}\n')
field('ellipse', '[0 0 0 0 0 0 0]', ell)
field('p', '[1 -1 -2 0 0 0 0]', pv)
w('0/rho', 'volScalarField', 'rho', 'dimensions [1 -3 0 0 0 0 0];\ninternalField uniform 1;\n'
  'boundaryField { walls { type zeroGradient; } frontAndBack { type empty; } }\n')
w('0/U', 'volVectorField', 'U', 'dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n'
  'boundaryField { walls { type slip; } frontAndBack { type empty; } }\n')
