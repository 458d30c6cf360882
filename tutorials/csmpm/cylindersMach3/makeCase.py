#!/usr/bin/python3
"""Write the posts-in-Mach-3 case (dissertation 3.3.2, Fig. 3.15, in 2D)
into directory D: python3 makeCase.py D [n=80] [tEnd=0.6] [write=0.02]
[material=neoHookean] [rhoS=20] [E=2e4] [nu=0.35] [yield=800] [M=3]
[substeps=1]

A channel [0, 1.5] x [0, 0.5] (n cells per unit length, square), walls at
the bottom and top, inlet on the left, outlet on the right; gas rho 1.4,
p 1 at rest (sound speed 1) and a Mach M shock at x = 0.1 moving right:
behind it (Rankine-Hugoniot, gamma 1.4; M 3: rho 5.4, u 2.222, p 10.33,
the flow at Mach 1.36), the state the inlet keeps (as liftingCylinder;
a channel started at Mach 3 everywhere empties the post's lee to p 1e-6
and stops there).  A post of
width 1/16 and height 0.25 (the cylinder of Fig. 3.15 seen from its side)
stands on the floor at x = 0.4, clamped there (MPM 'fixed' on the floor
vertices under it), 2 x 2 particles per cell; material neoHookean
(elastic) or henckyJ2 (von Mises plasticity, perfectly plastic at the
yield stress 'yield').  'substeps' is the coupling's solidSubsteps (the
most solid substeps in one gas step; 1: the post's elastic waves set the
step).
"""
import os, sys
a = dict(n=80, tEnd=0.6, write=0.02, material='neoHookean', rhoS=20.0,
         E=2.0e4, nu=0.35, M=3.0, substeps=1, **{'yield': 800.0})
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    a[k] = type(a[k])(v)
n = int(a['n']); dx = 1.0/n
nx, ny = (3*n)//2, n//2
g = 1.4; M = a['M']; rho1, p1 = 1.4, 1.0
c1 = (g*p1/rho1)**0.5
p2 = p1*(1 + 2*g/(g + 1)*(M*M - 1))
rho2 = rho1*(g + 1)*M*M/((g - 1)*M*M + 2)
u2 = c1*2*(M*M - 1)/((g + 1)*M)
H = 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
for sub in ('0', 'constant', 'system'):
    os.makedirs(os.path.join(d, sub), exist_ok=True)
def w(path, cls, obj, body):
    with open(os.path.join(d, path), 'w') as f:
        f.write(H % (cls, obj) + body)
w('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices ( (0 0 0) (1.5 0 0) (1.5 0.5 0) (0 0.5 0)
           (0 0 {dx}) (1.5 0 {dx}) (1.5 0.5 {dx}) (0 0.5 {dx}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {ny} 1) simpleGrading (1 1 1) );
boundary
(
    inlet  {{ type patch; faces ((0 4 7 3)); }}
    outlet {{ type patch; faces ((1 2 6 5)); }}
    walls  {{ type wall; faces ((0 1 5 4) (3 7 6 2)); }}
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
boundaries {{ inlet {{ type inlet; }} outlet {{ type outlet; }} }}
coupling {{ order couplingFirst; ghostInit ambient;
    solidSubsteps {int(a["substeps"])}; }}
''')
w('constant/thermophysicalProperties', 'dictionary',
  'thermophysicalProperties', 'gamma 1.4; R 1;\n')
mat = f'type {a["material"]}; rho {a["rhoS"]}; E {a["E"]}; nu {a["nu"]};'
if a['material'] == 'henckyJ2':
    mat += f' kappaP {a["yield"]}; kappaR {a["yield"]}; eta 0;'
x0, x1 = 0.4 - 1/32, 0.4 + 1/32
w('constant/mpmProperties', 'dictionary', 'mpmProperties', f'''
kernel bspline2; transfer APIC; CFL 0.5;
materials {{ post {{ {mat} }} }}
boundary
{{
    walls {{ type separable; }}
    root {{ type fixed; box (({x0 - 0.5*dx} -1 -1) ({x1 + 0.5*dx} {0.5*dx} 1)); }}
}}
''')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', f'''
regions ( post {{ type box; min ({x0} 0 -1); max ({x1} 0.25 1);
    material post; perCell 2; }} );
''')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{nx} {ny} {dx!r}\n')
xs = [((i % nx) + 0.5)*dx for i in range(nx*ny)]
shocked = lambda x: x < 0.1
def field(name, cls, dim, vals, inletValue, wall):
    kind = 'scalar' if cls == 'volScalarField' else 'vector'
    w('0/' + name, cls, name, f'dimensions {dim};\n'
      f'internalField nonuniform List<{kind}> {len(vals)}\n(\n'
      + '\n'.join(vals) + '\n);\n'
      f'boundaryField {{ inlet {{ type fixedValue; value uniform {inletValue}; }}'
      f' outlet {{ type zeroGradient; }} walls {{ type {wall}; }}'
      ' frontAndBack { type empty; } }\n')
field('p', 'volScalarField', '[1 -1 -2 0 0 0 0]',
      [repr(p2 if shocked(x) else p1) for x in xs], repr(p2), 'zeroGradient')
field('rho', 'volScalarField', '[1 -3 0 0 0 0 0]',
      [repr(rho2 if shocked(x) else rho1) for x in xs], repr(rho2), 'zeroGradient')
field('U', 'volVectorField', '[0 1 -1 0 0 0 0]',
      [f'({u2 if shocked(x) else 0.0!r} 0 0)' for x in xs], f'({u2!r} 0 0)', 'slip')
