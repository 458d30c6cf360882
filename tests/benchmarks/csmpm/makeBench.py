#!/usr/bin/python3
"""The CSMPM cost benchmark's case: python3 makeBench.py D n=256 steps=100 solid=1 spacing=S [L=1]

The unit square, n x n cells, walls; gas rho 1, p 1 at rest with p 5 in a
circle of radius 0.1 at (0.25, 0.5) (a blast); with solid=1 an elastic disk
(rho 10, E 1e4, neoHookean, bspline2, APIC) of radius 0.1 at (0.6, 0.5):
3.1 % of the cells.  L: the box [0, L]^2 (default 1), with
the blast and the disk where they are (n cells a side: L = 2 with 2n
cells is the same cell size on a lattice four times larger).  The time step is fixed at 5e-5 (maxDeltaT, below both
the gas's and the solid's stable steps), so every run takes the same steps.
"""
import os, sys
a = dict(n=256, steps=100, solid=1, spacing=1.0/512, L=1.0)
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    a[k] = type(a[k])(v)
n = int(a['n']); L = a['L']; dx = L/n; dt = 5e-5
H = 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
for sub in ('0', 'constant', 'system'):
    os.makedirs(os.path.join(d, sub), exist_ok=True)
def w(path, cls, obj, body):
    with open(os.path.join(d, path), 'w') as f:
        f.write(H % (cls, obj) + body)
w('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices ( (0 0 0) ({L} 0 0) ({L} {L} 0) (0 {L} 0) (0 0 {dx}) ({L} 0 {dx}) ({L} {L} {dx}) (0 {L} {dx}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({n} {n} 1) simpleGrading (1 1 1) );
boundary
(
    walls {{ type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
''')
w('system/controlDict', 'dictionary', 'controlDict', f'''
application shockMpmFoam; startFrom startTime; startTime 0; stopAt endTime;
endTime {a["steps"]*dt}; deltaT {dt}; writeControl adjustable;
writeInterval 1; purgeWrite 0; writeFormat binary;
writePrecision 12; writeCompression off; timeFormat general;
timePrecision 8; runTimeModifiable false;
''')
w('system/fvSchemes', 'dictionary', 'fvSchemes', '''
ddtSchemes { default Euler; } gradSchemes { default Gauss linear; }
divSchemes { default none; } laplacianSchemes { default none; }
interpolationSchemes { default linear; } snGradSchemes { default corrected; }
''')
w('system/fvSolution', 'dictionary', 'fvSolution', '\n')
w('system/shockMpmDict', 'dictionary', 'shockMpmDict', f'''
gas {{ stepper semiImplicit; scheme WENO5; timeIntegration RK3; CFL 0.5; maxDeltaT {dt}; }}
boundaries {{ }}
''')
w('constant/thermophysicalProperties', 'dictionary',
  'thermophysicalProperties', 'gamma 1.4; R 1;\n')
if a['solid']:
    w('constant/mpmProperties', 'dictionary', 'mpmProperties', f'''
kernel bspline2; transfer APIC; CFL 0.5; maxDeltaT {dt};
materials {{ disk {{ type neoHookean; rho 10; E 1e4; nu 0.3; }} }}
''')
    w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', f'''
regions ( disk {{ type cylinder; centre (0.6 0.5 0); radius 0.1; axis (0 0 1);
    material disk; spacing {a["spacing"]}; }} );
''')
w('system/setFieldsDict', 'dictionary', 'setFieldsDict', '''
defaultFieldValues ( volScalarFieldValue p 1 );
regions ( cylinderToCell { p1 (0.25 0.5 -1); p2 (0.25 0.5 1); radius 0.1;
    fieldValues ( volScalarFieldValue p 5 ); } );
''')
for name, cls, dim, val in (('p', 'volScalarField', '[1 -1 -2 0 0 0 0]', 'uniform 1'),
                             ('rho', 'volScalarField', '[1 -3 0 0 0 0 0]', 'uniform 1'),
                             ('U', 'volVectorField', '[0 1 -1 0 0 0 0]', 'uniform (0 0 0)')):
    bc = 'slip' if name == 'U' else 'zeroGradient'
    w('0/' + name, cls, name, f'dimensions {dim};\ninternalField {val};\n'
      f'boundaryField {{ walls {{ type {bc}; }} frontAndBack {{ type empty; }} }}\n')
