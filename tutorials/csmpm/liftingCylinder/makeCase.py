#!/usr/bin/python3
"""Write the lifting-cylinder case (dissertation 3.3.1, Fig. 3.7; the shock-
induced lift-off of Falcovitz et al. 1997, Arienti et al. 2003) into
directory D: python3 makeCase.py D [nx=250] [tEnd=0.255] [write=0.05]
[rhoS=10.77] [E=1e4] [nu=0.3] [M=3] [maxSteps=1e9] [kernel=bspline2]
[order=couplingFirst]

Channel [0, 1] x [0, 0.2], walls at the bottom and top, inlet on the left,
outlet on the right.  Gas rho 1.4, p 1 at rest (sound speed 1), a Mach 3
shock at x = 0.08 moving right: post-shock rho 5.4, u 2.2222, p 10.333
(Rankine-Hugoniot, gamma 1.4), which the inlet keeps.  A cylinder of radius
0.05 resting on the bottom wall at x = 0.15, density 10.77 (7.7 times the
gas's), stiff (E 1e4 against pressures of about 10: strains of 1e-3).
"""
import os, sys
a = dict(nx=250, tEnd=0.255, write=0.05, rhoS=10.77, E=1.0e4, nu=0.3,
         kernel='bspline2', order='couplingFirst', perCell=2, M=3.0,
         maxSteps=1e9)
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    a[k] = type(a[k])(v)
nx = int(a['nx']); ny = nx//5; dx = 1.0/nx
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
vertices ( (0 0 0) (1 0 0) (1 0.2 0) (0 0.2 0)
           (0 0 {dx}) (1 0 {dx}) (1 0.2 {dx}) (0 0.2 {dx}) );
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
writePrecision 12; writeCompression off; timeFormat general;
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
coupling {{ order {a["order"]}; ghostInit ambient; }}
''')
w('constant/thermophysicalProperties', 'dictionary',
  'thermophysicalProperties', 'gamma 1.4; R 1;\n')
w('constant/mpmProperties', 'dictionary', 'mpmProperties', f'''
kernel {a["kernel"]}; transfer APIC; CFL 0.5; maxSteps {a["maxSteps"]};
materials {{ cylinder {{ type neoHookean; rho {a["rhoS"]}; E {a["E"]}; nu {a["nu"]}; }} }}
boundary {{ walls {{ type separable; }} }}
''')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', f'''
regions ( cylinder {{ type cylinder; centre (0.15 0.05 0); radius 0.05;
    axis (0 0 1); material cylinder; perCell {a["perCell"]}; }} );
''')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{nx} {ny}\n')
xs = [((i % nx) + 0.5)*dx for i in range(nx*ny)]
def field(name, cls, dim, vals, bc):
    kind = 'scalar' if cls == 'volScalarField' else 'vector'
    body = f'dimensions {dim};\ninternalField nonuniform List<{kind}> {len(vals)}\n(\n'
    body += '\n'.join(vals) + '\n);\nboundaryField\n{\n' + bc + '    frontAndBack { type empty; }\n}\n'
    w('0/' + name, cls, name, body)
shocked = lambda x: x < 0.08
def bc(inletValue):
    return (f'    inlet {{ type fixedValue; value uniform {inletValue}; }}\n'
            '    outlet { type zeroGradient; }\n')
field('p', 'volScalarField', '[1 -1 -2 0 0 0 0]',
      [repr(p2 if shocked(x) else p1) for x in xs],
      bc(repr(p2)) + '    walls { type zeroGradient; }\n')
field('rho', 'volScalarField', '[1 -3 0 0 0 0 0]',
      [repr(rho2 if shocked(x) else rho1) for x in xs],
      bc(repr(rho2)) + '    walls { type zeroGradient; }\n')
field('U', 'volVectorField', '[0 1 -1 0 0 0 0]',
      [f'({u2 if shocked(x) else 0.0!r} 0 0)' for x in xs],
      bc(f'({u2!r} 0 0)') + '    walls { type slip; }\n')
