#!/usr/bin/python3
"""Write the exploding-shell case (dissertation 3.3.2, Fig. 3.10) into
directory D: python3 makeCase.py D [n=256] [tEnd=0.12] [write=0.005]
[pIn=50] [rhoIn=7] [rhoS=10] [E=100] [nu=0.3] [rIn=0.1] [rOut=0.12]
[material=neoHookean] [yield=5] [notches=0] [cx=0.5] [cy=0.5] [ux=0] [uy=0]
[vary=0.05] [seed=1] [walls=0]

The unit square, outlets all round (the far field at rest); gas rho 1.4,
p 1 (sound speed 1) outside, hot compressed gas (rhoIn, pIn: sound speed
sqrt(1.4 pIn/rhoIn)) inside an elastic ring of radii rIn and rOut centred
at (0.5, 0.5) (neoHookean, rho 10, E 100, nu 0.3: Table 3.1's), its
cells (topoSet cylinderAnnulusToCell) filled with 2 x 2 particles each.
'notches' slots of one cell's width cut through the ring at equal angles
(the first at 45 degrees) score it like a grenade's case (default 0: the
ring breaks where MPM breaks it).
material henckyJ2 makes the shell plastic (yield stress 'yield').
(cx, cy) moves the shell and its hot gas off the centre, (ux, uy) gives
the shell a drift velocity (a scene with momentum, for the tests).
vary > 0 gives the ring a seeded random density heterogeneity: each
particle's mass times 1 + vary xi, xi uniform in [-1, 1] hashed from seed
and its position (mpmSetParticles' densityVariation; default 0.05, so
that where the perfect ring breaks is the material's, not round-off's).  walls=1 closes the
box (reflective walls for the gas and the solid) instead of outlets.
"""
import math, os, sys
a = dict(n=256, tEnd=0.12, write=0.005, pIn=50.0, rhoIn=7.0, rhoS=10.0,
         E=100.0, nu=0.3, rIn=0.1, rOut=0.12, material='neoHookean',
         notches=0, cx=0.5, cy=0.5, ux=0.0, uy=0.0, vary=0.05, seed=1, walls=0,
         **{'yield': 5.0})
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
    open {{ type {'wall' if a['walls'] else 'patch'}; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
''')
cx, cy = a['cx'], a['cy']
notch = ''
for k in range(int(a['notches'])):
    th = math.pi/4 + 2*math.pi*k/int(a['notches'])
    c, s = math.cos(th), math.sin(th)
    L = 1.3*a['rOut'] - 0.7*a['rIn']; h = dx
    ox = cx + 0.7*a['rIn']*c + 0.5*h*s; oy = cy + 0.7*a['rIn']*s - 0.5*h*c
    notch += (f'    {{ name shell; type cellSet; action delete; source rotatedBoxToCell;'
              f' origin ({ox} {oy} -1); i ({L*c} {L*s} 0); j ({-h*s} {h*c} 0);'
              f' k (0 0 2); }}\n')
w('system/topoSetDict', 'dictionary', 'topoSetDict', f'''
actions
(
    {{ name shell; type cellSet; action new; source cylinderAnnulusToCell;
       p1 ({cx} {cy} -1); p2 ({cx} {cy} 1); outerRadius {a["rOut"]}; innerRadius {a["rIn"]}; }}
{notch}    {{ name shell; type cellZoneSet; action new; source setToCellZone; set shell; }}
    {{ name hot; type cellSet; action new; source cylinderToCell;
       p1 ({cx} {cy} -1); p2 ({cx} {cy} 1); radius {a["rIn"]}; }}
);
''')
w('system/setFieldsDict', 'dictionary', 'setFieldsDict', f'''
defaultFieldValues ( volScalarFieldValue p 1 volScalarFieldValue rho 1.4 );
regions ( cellToCell {{ set hot; fieldValues ( volScalarFieldValue p {a["pIn"]}
    volScalarFieldValue rho {a["rhoIn"]} ); }} );
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
w('system/shockMpmDict', 'dictionary', 'shockMpmDict', '''
gas { stepper semiImplicit; scheme WENO5; timeIntegration RK3; CFL 0.5; }
boundaries { open { type %s; } }
coupling { order couplingFirst; ghostInit ambient; }
''' % ('wall' if a['walls'] else 'outlet'))
w('constant/thermophysicalProperties', 'dictionary',
  'thermophysicalProperties', 'gamma 1.4; R 1;\n')
mat = f'type {a["material"]}; rho {a["rhoS"]}; E {a["E"]}; nu {a["nu"]};'
if a['material'] == 'henckyJ2':
    mat += f' kappaP {a["yield"]}; kappaR {a["yield"]}; eta 0;'
w('constant/mpmProperties', 'dictionary', 'mpmProperties', f'''
kernel bspline2; transfer APIC; CFL 0.5;
materials {{ shell {{ {mat} }} }}
boundary {{ open {{ type {'slip' if a['walls'] else 'outlet'}; }} }}
''')
vary = (f' densityVariation {{ amplitude {a["vary"]}; seed {int(a["seed"])}; }}'
        if a['vary'] > 0 else '')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', f'''
regions ( shell {{ type cellZone; zone shell; material shell; perCell 2;
    velocity ({a["ux"]} {a["uy"]} 0);{vary} }} );
''')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{n} {n} {dx!r}\n')
for name, cls, dim, val in (('p', 'volScalarField', '[1 -1 -2 0 0 0 0]', 'uniform 1'),
                             ('rho', 'volScalarField', '[1 -3 0 0 0 0 0]', 'uniform 1.4'),
                             ('U', 'volVectorField', '[0 1 -1 0 0 0 0]', 'uniform (0 0 0)')):
    bc = 'slip' if a['walls'] and name == 'U' else 'zeroGradient'
    w('0/' + name, cls, name, f'dimensions {dim};\ninternalField {val};\n'
      f'boundaryField {{ open {{ type {bc}; }} frontAndBack {{ type empty; }} }}\n')
