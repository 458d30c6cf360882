#!/usr/bin/python3
"""Write a 1D CSMPM case into directory D: python3 makeCase.py D key=value...

keys: L (length), n (cells), left/right (gas patch kinds: inlet, outlet,
wall), gas states rhoL uL pL (x < x0) and rhoR uR pR, x0, slab (xmin xmax),
rhoS, E, nu, vS (slab velocity), tEnd, write (interval), mpmCFL,
maxRetries (the gas's), treatment (of particles that would invert: clamp
or stop), mpmRight (the MPM grid's condition on the right end: free,
slip or fixed).
"""
import os, sys
a = dict(L=1.0, n=400, left='wall', right='wall', x0=-1.0,
         rhoL=1.0, uL=0.0, pL=1.0, rhoR=1.0, uR=0.0, pR=1.0,
         xs0=0.8, xs1=0.9, rhoS=1000.0, E=1000.0, nu=0.25, vS=0.0,
         xa=-1.0, CGtol=1e-10, kernel="bspline2", tEnd=0.5, write=0.25, mpmCFL=0.5, order='couplingFirst',
         ghostInit='ambient', maxRetries=5, treatment='clamp', mpmRight='free')
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    a[k] = type(a[k])(v) if k in a else v
n = int(a['n']); L = a['L']; dx = L/n
H = 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
for sub in ('0', 'constant', 'system'):
    os.makedirs(os.path.join(d, sub), exist_ok=True)
def w(path, cls, obj, body):
    with open(os.path.join(d, path), 'w') as f:
        f.write(H % (cls, obj) + body)
w('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices ( (0 0 0) ({L} 0 0) ({L} {dx} 0) (0 {dx} 0)
           (0 0 {dx}) ({L} 0 {dx}) ({L} {dx} {dx}) (0 {dx} {dx}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({n} 1 1) simpleGrading (1 1 1) );
boundary
(
    left  {{ type patch; faces ((0 4 7 3)); }}
    right {{ type patch; faces ((1 2 6 5)); }}
    empty {{ type empty; faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }}
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
gas {{ stepper semiImplicit; scheme WENO5; timeIntegration RK3; CFL 0.5; CGtolerance {a["CGtol"]};
      maxRetries {a["maxRetries"]}; }}
boundaries {{ left {{ type {a["left"]}; }} right {{ type {a["right"]}; }} }}
coupling {{ order {a["order"]}; ghostInit {a["ghostInit"]}; }}
''')
w('constant/thermophysicalProperties', 'dictionary',
  'thermophysicalProperties', 'gamma 1.4; R 1;\n')
w('constant/mpmProperties', 'dictionary', 'mpmProperties', f'''
kernel {a["kernel"]}; transfer FLIP; CFL {a["mpmCFL"]};
materials {{ slab {{ type linearElastic; rho {a["rhoS"]}; E {a["E"]}; nu {a["nu"]}; }} }}
inversion {{ treatment {a["treatment"]}; }}
boundary {{ right {{ type {a["mpmRight"]}; }} }}
''')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', f'''
regions ( slab {{ type box; min ({a["xs0"]} -1 -1); max ({a["xs1"]} 1 1);
    material slab; perCell 2; velocity ({a["vS"]} 0 0); }} );
''')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{L} {n}\n')
xs = [(i + 0.5)*dx for i in range(n)]
def field(name, cls, dim, vals, bc):
    body = f'dimensions {dim};\ninternalField nonuniform List<{ "scalar" if cls == "volScalarField" else "vector"}> {n}\n(\n'
    body += '\n'.join(vals) + '\n);\nboundaryField\n{\n' + bc + '    empty { type empty; }\n}\n'
    w('0/' + name, cls, name, body)
def side(k): return 'L' if a['xa'] <= k < a['x0'] else 'R'
bcS = lambda v: ''.join(f'    {p} {{ type zeroGradient; }}\n' for p in ('left', 'right'))
field('p', 'volScalarField', '[1 -1 -2 0 0 0 0]', [repr(a['p' + side(x)]) for x in xs], bcS(0))
field('rho', 'volScalarField', '[1 -3 0 0 0 0 0]', [repr(a['rho' + side(x)]) for x in xs], bcS(0))
field('U', 'volVectorField', '[0 1 -1 0 0 0 0]', [f'({a["u" + side(x)]!r} 0 0)' for x in xs],
      ''.join(f'    {p} {{ type zeroGradient; }}\n' for p in ('left', 'right')))
