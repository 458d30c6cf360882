#!/usr/bin/python3
"""Write the 2D bullet case (dissertation 3.3.2, Fig. 3.12) into directory
D: python3 makeCase.py D [n=80] [tEnd=0.8] [write=0.01] [rhoS=100]
[E=1e6] [nu=0.25] [pC=50] [rhoC=7] [corner=none] [gap=0]

A gun: the barrel is the channel x in [0, 1], y in [0.4, 0.6] (walls:
the breech at x = 0 and the bore, patch 'barrel'; the gun's front face at
x = 1, patch 'face'), opening into the air x in [1, 2.5], y in [0, 1]
(outlets at x = 2.5, y = 0 and y = 1).  n cells per unit length (square
cells; n a multiple of 10: the bore is n/5 cells wide).  Air rho 1.4, p 1
at rest (sound speed 1); the chamber x < 0.2 holds hot compressed gas
(pC, rhoC: by default 50 and 7, ten times the air's temperature, sound
speed 3.16).  The bullet fills the bore from x = 0.2 to 0.35: density
rhoS (the heavy bullet 100, the light one 40: the dissertation's 1250 and
500 in the ratio 2.5), neoHookean E 1e6 (Table 3.1's), nu 0.25 (strains
of 5e-5 under the chamber pressure), sliding on the bore (MPM slip on 'barrel').  'gap'
narrows the bullet by that much on each side (windage; 0: it fills the
bore); 'corner' is the gas solver's cornerTreatment.
"""
import os, sys
a = dict(n=80, tEnd=0.8, write=0.01, rhoS=100.0, E=1.0e6, nu=0.25,
         pC=50.0, rhoC=7.0, corner='none', gap=0.0)
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    a[k] = type(a[k])(v)
n = int(a['n'])
if n % 10:
    sys.exit('makeCase.py: n must be a multiple of 10, got %d' % n)
dx = 1.0/n; z = dx
H = 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
for sub in ('0', 'constant', 'system'):
    os.makedirs(os.path.join(d, sub), exist_ok=True)
def w(path, cls, obj, body):
    with open(os.path.join(d, path), 'w') as f:
        f.write(H % (cls, obj) + body)
# vertices: barrel 0-3, open region 4-11 (z = 0), then the same at z = dx
pts = [(0, 0.4), (1, 0.4), (1, 0.6), (0, 0.6),
       (1, 0), (2.5, 0), (2.5, 0.4), (2.5, 0.6), (2.5, 1), (1, 1)]
# indices: 0 (0,.4) 1 (1,.4) 2 (1,.6) 3 (0,.6) 4 (1,0) 5 (2.5,0)
#          6 (2.5,.4) 7 (2.5,.6) 8 (2.5,1) 9 (1,1); +10 at z = dx
N = len(pts)
verts = '\n'.join(f'    ({x} {y} 0)' for x, y in pts) + '\n' + \
        '\n'.join(f'    ({x} {y} {z})' for x, y in pts)
def hexb(a_, b, c, d_, nx, ny):
    return (f'    hex ({a_} {b} {c} {d_} {a_ + N} {b + N} {c + N} {d_ + N}) '
            f'({nx} {ny} 1) simpleGrading (1 1 1)')
def face(a_, b):
    return f'({a_} {b} {b + N} {a_ + N})'
nb, nw, nl, nh = n, n//5, 3*n//2, 2*n//5
w('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices
(
{verts}
);
blocks
(
{hexb(0, 1, 2, 3, nb, nw)}
{hexb(4, 5, 6, 1, nl, nh)}
{hexb(1, 6, 7, 2, nl, nw)}
{hexb(2, 7, 8, 9, nl, nh)}
);
boundary
(
    barrel {{ type wall; faces ({face(3, 0)} {face(0, 1)} {face(2, 3)}); }}
    face   {{ type wall; faces ({face(1, 4)} {face(9, 2)}); }}
    open   {{ type patch; faces ({face(4, 5)} {face(5, 6)} {face(6, 7)}
                                {face(7, 8)} {face(8, 9)}); }}
    frontAndBack {{ type empty; faces (
        (0 3 2 1) (4 1 6 5) (1 2 7 6) (2 9 8 7)
        ({N} {N + 1} {N + 2} {N + 3}) ({N + 4} {N + 5} {N + 6} {N + 1})
        ({N + 1} {N + 6} {N + 7} {N + 2}) ({N + 2} {N + 7} {N + 8} {N + 9})); }}
);
''')
w('system/topoSetDict', 'dictionary', 'topoSetDict', '''
actions
(
    { name chamber; type cellSet; action new; source boxToCell;
      box (-1 0.3 -1) (0.2 0.7 1); }
);
''')
w('system/setFieldsDict', 'dictionary', 'setFieldsDict', f'''
defaultFieldValues ( volScalarFieldValue p 1 volScalarFieldValue rho 1.4 );
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
coupling {{ order couplingFirst; ghostInit ambient; }}
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
    f.write(f'{n} {n} {dx!r} {a["rhoS"]!r} {a["pC"]!r} {a["rhoC"]!r}\n')
for name, cls, dim, val in (('p', 'volScalarField', '[1 -1 -2 0 0 0 0]', 'uniform 1'),
                             ('rho', 'volScalarField', '[1 -3 0 0 0 0 0]', 'uniform 1.4'),
                             ('U', 'volVectorField', '[0 1 -1 0 0 0 0]', 'uniform (0 0 0)')):
    wall = 'slip' if name == 'U' else 'zeroGradient'
    w('0/' + name, cls, name, f'dimensions {dim};\ninternalField {val};\n'
      f'boundaryField {{ "barrel|face" {{ type {wall}; }} open {{ type zeroGradient; }}'
      ' frontAndBack { type empty; } }\n')
