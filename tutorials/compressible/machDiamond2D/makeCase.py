#!/usr/bin/python3
"""Write the 2D Mach-diamond case (dissertation 3.3.2, Fig. 3.18) into
directory D: python3 makeCase.py D [nx=192] [tEnd=1.4] [write=0.35]
[M=3] [pRatio=0.5] [stepper=explicit]

The box [0, 1] x [0, 1.5] of gas at rest, rho 1.4, p 1 (sound speed 1).
The central 1/8 of the bottom (x in [7/16, 9/16]) is the nozzle: an inlet
blowing upward at Mach M with pRatio times the ambient pressure, at the
ambient temperature (rho 1.4 pRatio, sound speed 1, U = M): an
over-expanded jet.  The rest of the bottom is a wall; the sides and the
top are outlets (ghosts extrapolated, the far field at rest).  Square cells
of 1/nx (nx a multiple of 16), three blocks side by side.
"""
import os, sys
a = dict(nx=192, tEnd=1.4, write=0.35, M=3.0, pRatio=0.5,
         stepper='explicit')
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    a[k] = type(a[k])(v)
nx = int(a['nx'])
if nx % 16:
    sys.exit('makeCase.py: nx must be a multiple of 16, got %d' % nx)
dx = 1.0/nx; ny = (3*nx)//2
n1, n2 = 7*nx//16, nx//8
rhoA, pA = 1.4, 1.0
pJ = a['pRatio']*pA; rhoJ = rhoA*a['pRatio']; uJ = a['M']*(1.4*pJ/rhoJ)**0.5
H = 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
for sub in ('0', 'constant', 'system'):
    os.makedirs(os.path.join(d, sub), exist_ok=True)
def w(path, cls, obj, body):
    with open(os.path.join(d, path), 'w') as f:
        f.write(H % (cls, obj) + body)
x1, x2 = 7/16, 9/16
w('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices
(
    (0 0 0) ({x1} 0 0) ({x2} 0 0) (1 0 0)
    (0 1.5 0) ({x1} 1.5 0) ({x2} 1.5 0) (1 1.5 0)
    (0 0 {dx}) ({x1} 0 {dx}) ({x2} 0 {dx}) (1 0 {dx})
    (0 1.5 {dx}) ({x1} 1.5 {dx}) ({x2} 1.5 {dx}) (1 1.5 {dx})
);
blocks
(
    hex (0 1 5 4 8 9 13 12) ({n1} {ny} 1) simpleGrading (1 1 1)
    hex (1 2 6 5 9 10 14 13) ({n2} {ny} 1) simpleGrading (1 1 1)
    hex (2 3 7 6 10 11 15 14) ({n1} {ny} 1) simpleGrading (1 1 1)
);
boundary
(
    nozzle {{ type patch; faces ((1 2 10 9)); }}
    floor  {{ type wall; faces ((0 1 9 8) (2 3 11 10)); }}
    open   {{ type patch; faces ((0 8 12 4) (3 7 15 11) (4 12 13 5)
                                (5 13 14 6) (6 14 15 7)); }}
    frontAndBack {{ type empty; faces ((0 4 5 1) (1 5 6 2) (2 6 7 3)
                                      (8 9 13 12) (9 10 14 13) (10 11 15 14)); }}
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
gas {{ stepper {a["stepper"]}; scheme WENO5; timeIntegration RK3; CFL 0.5; }}
boundaries {{ nozzle {{ type inlet; }} open {{ type outlet; }} }}
''')
w('constant/thermophysicalProperties', 'dictionary',
  'thermophysicalProperties', 'gamma 1.4; R 1;\n')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{nx} {ny} {dx!r} {a["M"]!r} {pJ!r} {rhoJ!r} {uJ!r}\n')
def field(name, cls, dim, internal, nozzle, wallBc):
    w('0/' + name, cls, name, f'dimensions {dim};\ninternalField uniform {internal};\n'
      f'boundaryField\n{{\n    nozzle {{ type fixedValue; value uniform {nozzle}; }}\n'
      f'    floor {{ type {wallBc}; }}\n    open {{ type zeroGradient; }}\n'
      '    frontAndBack { type empty; }\n}\n')
field('p', 'volScalarField', '[1 -1 -2 0 0 0 0]', repr(pA), repr(pJ), 'zeroGradient')
field('rho', 'volScalarField', '[1 -3 0 0 0 0 0]', repr(rhoA), repr(rhoJ), 'zeroGradient')
field('U', 'volVectorField', '[0 1 -1 0 0 0 0]', '(0 0 0)', f'(0 {uJ!r} 0)', 'slip')
