#!/usr/bin/python3
"""Write one granular column collapse case into directory D:
python3 makeCase.py D [a=0.5] [L0=0.2] [h=0.005] [tEnd=1.0] [write=0.025]
[rho=1600] [E=1e6] [nu=0.3] [phi=21] [psi=0] [kernel=umls]
[transfer=FLIP]

A column of dry sand (Drucker-Prager, no cohesion) L0 long and H0 = a L0
high stands against the left wall x = 0 of a plane-strain channel and is
released at t = 0 (gravity switched on, no gate).  The background mesh is a
uniform blockMesh of square cells of size h, one layer thick, x in [0, Lx]
(long enough for the run-out of the scaling law plus margin), y in
[0, Ly] (above the column).  Particles on a lattice of spacing h/2 (2 x 2
per cell).  Floor: no-slip (grid condition fixed), standing for a rough
base; left wall: slip (the channel's back wall); right and top: free.
"""
import os, sys
a = dict(a=0.5, L0=0.2, h=0.005, tEnd=1.0, write=0.025, rho=1600.0,
         E=1.0e6, nu=0.3, phi=21.0, psi=0.0, kernel='umls', transfer='FLIP')
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    a[k] = type(a[k])(v)
L0, h = a['L0'], a['h']
H0 = a['a']*L0
# Lube et al. (2005): (L - L0)/L0 = 1.2 a (a < 1.8), 1.9 a^(2/3) (a > 2.8);
# room for twice that
law = 1.2*a['a'] if a['a'] < 2.3 else 1.9*a['a']**(2.0/3.0)
nx = int(round(L0*(1 + 2*law)/h)) + 4
ny = int(round(1.1*H0/h)) + 2
Lx, Ly = nx*h, ny*h
H = 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
for sub in ('constant', 'system'):
    os.makedirs(os.path.join(d, sub), exist_ok=True)
def w(path, obj, body):
    with open(os.path.join(d, path), 'w') as f:
        f.write('// mpmFoam tutorial mpm/columnCollapse2D, written by makeCase.py\n')
        f.write(H % ('dictionary', obj) + body)
w('system/blockMeshDict', 'blockMeshDict', f'''
// {Lx:g} x {Ly:g} m, square cells h = {h:g} m, one layer (plane strain)
vertices ( (0 0 0) ({Lx} 0 0) ({Lx} {Ly} 0) (0 {Ly} 0)
           (0 0 {h}) ({Lx} 0 {h}) ({Lx} {Ly} {h}) (0 {Ly} {h}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {ny} 1) simpleGrading (1 1 1) );
boundary
(
    floor  {{ type wall; faces ((0 1 5 4)); }}
    back   {{ type wall; faces ((0 4 7 3)); }}
    open   {{ type patch; faces ((1 2 6 5) (3 7 6 2)); }}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
''')
w('system/controlDict', 'controlDict', f'''
libs            ("libmpmFoamFunctionObjects.so");
application     umlsMpmFoam;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         {a["tEnd"]};
deltaT          1e-5;
writeControl    adjustableRunTime;
writeInterval   {a["write"]};
purgeWrite      0;
writeFormat     ascii;
writePrecision  10;
timeFormat      general;
timePrecision   6;
runTimeModifiable false;
functions
{{
    conservation
    {{
        type    mpmConservation;
        libs    ("libmpmFoamFunctionObjects.so");
    }}
}}
''')
w('system/fvSchemes', 'fvSchemes', '''
ddtSchemes { default none; } gradSchemes { default none; }
divSchemes { default none; } laplacianSchemes { default none; }
interpolationSchemes { default linear; } snGradSchemes { default none; }
''')
w('system/fvSolution', 'fvSolution', '\n')
w('constant/mpmProperties', 'mpmProperties', f'''
kernel      {a["kernel"]};
transfer    {a["transfer"]};
flipRatio   0.99;
CFL         0.4;
gravity     (0 -9.81 0);
logInterval 1000;

materials
{{
    sand
    {{
        type            druckerPrager;
        rho             {a["rho"]};
        E               {a["E"]};
        nu              {a["nu"]};
        frictionAngle   {a["phi"]};
        dilatancyAngle  {a["psi"]};
        cohesion        0;
    }}
}}

boundary
{{
    floor {{ type fixed; }}       // no-slip: a rough base
    back  {{ type slip; }}        // the channel's back wall
}}
''')
w('system/mpmSetParticlesDict', 'mpmSetParticlesDict', f'''
// The column: L0 = {L0:g} m, H0 = {H0:g} m (a = {a["a"]:g}), 2 x 2 particles per cell
regions
(
    column
    {{
        type        box;
        min         (0 0 0);
        max         ({L0} {H0} {h});
        material    sand;
        spacing     {h/2};
    }}
);
''')
print(f"{d}: a = {a['a']:g}, L0 = {L0:g} m, H0 = {H0:g} m, mesh {nx} x {ny} (h = {h:g} m)")
