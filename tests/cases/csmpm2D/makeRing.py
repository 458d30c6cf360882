#!/usr/bin/python3
"""Write the quiescent-ring case (dissertation Fig. 3.3) into directory D:
python3 makeRing.py D [n=128] [tEnd=0.7] [ghostInit=ambient] [kernel=bspline2]
    [solidUpdate=eliminated] [E=1e3] [rhoS=10] [periodic=0] [pulse=0]

The unit square, walls all round, gas rho 1, p 1 at rest (sound speed
1.183); an elastic ring (neoHookean, rho 10, E 1e3, nu 0.3) of radii 0.15
and 0.2 around the centre, the cells of the annulus (topoSet
cylinderAnnulusToCell) filled with 2 x 2 particles each.
ghostInit ambient: J^g = 1 - p/lambda^g, so the ghost pressure (3.17) is
the ambient pressure and the ring starts in equilibrium with the gas;
unstressed: J^g = 1, the ring starts with no pressure against the gas's 1.
periodic=1: cyclic patches left/right and bottom/top instead of the walls
(a closed system without walls: gas + solid momentum is conserved);
pulse=A: a pressure pulse p = 1 + A exp(-r^2/0.004) at (0.25, 0.55), to the
ring's left and off its axis, which pushes and turns it.
"""
import os, sys
a = dict(n=128, tEnd=0.7, write=0.35, ghostInit='ambient', kernel='bspline2',
         solidUpdate='eliminated', E=1e3, rhoS=10.0, periodic=0, pulse=0.0)
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
periodic = int(a['periodic'])
sides = ('''    left   { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }
    right  { type cyclic; neighbourPatch left; faces ((1 2 6 5)); }
    bottom { type cyclic; neighbourPatch top; faces ((0 1 5 4)); }
    top    { type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }'''
         if periodic else
         '''    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }''')
w('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 {dx}) (1 0 {dx}) (1 1 {dx}) (0 1 {dx}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({n} {n} 1) simpleGrading (1 1 1) );
boundary
(
{sides}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
''')
w('system/topoSetDict', 'dictionary', 'topoSetDict', f'''
actions
(
    {{ name ring; type cellSet; action new; source cylinderAnnulusToCell;
       p1 (0.5 0.5 -1); p2 (0.5 0.5 1); outerRadius 0.2; innerRadius 0.15; }}
    {{ name ring; type cellZoneSet; action new; source setToCellZone; set ring; }}
);
''')
w('system/controlDict', 'dictionary', 'controlDict', f'''
application shockMpmFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime {a["tEnd"]}; deltaT 1e-6; writeControl adjustable;
writeInterval {a["write"]}; purgeWrite 0; writeFormat ascii;
writePrecision 17; writeCompression off; timeFormat general;
timePrecision 8; runTimeModifiable false;
''')
w('system/fvSchemes', 'dictionary', 'fvSchemes', '''
ddtSchemes { default Euler; } gradSchemes { default Gauss linear; }
divSchemes { default none; } laplacianSchemes { default none; }
interpolationSchemes { default linear; } snGradSchemes { default corrected; }
''')
w('system/fvSolution', 'dictionary', 'fvSolution', '\n')
w('system/shockMpmDict', 'dictionary', 'shockMpmDict', f'''
gas {{ stepper semiImplicit; scheme WENO5; timeIntegration RK3; CFL 0.5; CGtolerance 1e-12; }}
boundaries {{ }}
coupling {{ order couplingFirst; ghostInit {a["ghostInit"]}; solidUpdate {a["solidUpdate"]}; }}
''')
w('constant/thermophysicalProperties', 'dictionary',
  'thermophysicalProperties', 'gamma 1.4; R 1;\n')
w('constant/mpmProperties', 'dictionary', 'mpmProperties', f'''
kernel {a["kernel"]}; transfer APIC; CFL 0.5;
materials {{ ring {{ type neoHookean; rho {a["rhoS"]}; E {a["E"]}; nu 0.3; }} }}
''')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', '''
regions ( ring { type cellZone; zone ring; material ring; perCell 2; } );
''')
import math
pInit = 'uniform 1'
if a['pulse'] != 0:
    vals = []
    for j in range(n):
        for i in range(n):
            x, y = (i + 0.5)*dx, (j + 0.5)*dx
            r2 = (x - 0.25)**2 + (y - 0.55)**2
            vals.append('%.17g' % (1 + a['pulse']*math.exp(-r2/0.004)))
    pInit = 'nonuniform List<scalar> %d (\n%s\n)' % (n*n, '\n'.join(vals))
for name, cls, dim, val in (('p', 'volScalarField', '[1 -1 -2 0 0 0 0]', pInit),
                             ('rho', 'volScalarField', '[1 -3 0 0 0 0 0]', 'uniform 1'),
                             ('U', 'volVectorField', '[0 1 -1 0 0 0 0]', 'uniform (0 0 0)')):
    if periodic:
        bf = ''.join('%s { type cyclic; } ' % q for q in ('left', 'right', 'bottom', 'top'))
    else:
        bf = 'walls { type %s; } ' % ('slip' if name == 'U' else 'zeroGradient')
    w('0/' + name, cls, name, f'dimensions {dim};\ninternalField {val};\n'
      f'boundaryField {{ {bf}frontAndBack {{ type empty; }} }}\n')
