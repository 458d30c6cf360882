#!/usr/bin/python3
"""Write one slope-failure case (dissertation 2.3.4, Fig. 2.20) into
directory D: python3 makeCase.py D [kernel=umls] [h=0.5] [H=8] [beta=60]
[crest=12] [floor=20] [depth=1] [tEnd=6] [write=0.25] [transfer=FLIP] [flip=0.99]
[structured=1] [tet=1] [support=mean] [update=USL] [step=vertex] [CFL=0.4]

Geometry (the dissertation gives the figure, not the numbers; these are
chosen here): a slope of sensitive clay H high at beta degrees, its crest
running back 'crest' m to the back wall x = 0, on a flat base with 'floor'
m of free run-out ahead of the toe; 'depth' m across (z), rollers on both
sides, so the failure is the plane-strain one of a long slope, cut to a
thin slice to keep the run short.  Base y = 0 fixed, back wall and the
two sides rollers (slip), front and top free.  Clay of 2.3.4: henckyJ2,
E 25 MPa, nu 0.499, kappaP 40.82 kPa, kappaR 2.45 kPa, eta 5, rho 2150,
Fbar on.

kernel umls: a gmsh tetrahedral mesh (slopeFailure3D.geo, run gmsh +
gmshToFoam yourself: see Allrun): structured=1 the cubes h cut into 6
tetrahedra each (the vertices of the bspline2 mesh), structured=0 gmsh's
unstructured tetrahedra of size tet*h; support: the umls kernel's
supportSize (mean or maxEdge edge of the vertex, or graded: the sizing
field over the longest edges; ring: mlsRing on the ring reach with the
weights' own gradient and the adaptive profile instead); step: mpmProperties' stepLength (vertex:
the shortest mean edge sets the step; kernel: the narrowest umls
support).  kernel bspline2: a
blockMesh of cubes h.  Particles on a lattice of spacing h/2, the same in both:
particle columns of width h/2 up to the slope's surface at their centre.
"""
import math, os, sys
a = dict(kernel='umls', h=0.5, H=8.0, beta=60.0, crest=12.0, floor=20.0,
         depth=1.0, tEnd=6.0, write=0.25, transfer='FLIP', flip=0.99, structured=1, tet=1.0,
         support='mean', update='USL', step='vertex', CFL=0.4)
d = sys.argv[1]
for kv in sys.argv[2:]:
    k, v = kv.split('=')
    a[k] = type(a[k])(v)
h, H, D = a['h'], a['H'], a['depth']
run = H/math.tan(math.radians(a['beta']))
toe = a['crest'] + run
nx = int(math.ceil((toe + a['floor'])/h))
ny = int(math.ceil((H + 2*h)/h))
nz = max(1, int(round(D/h)))
Lx, Ly, D = nx*h, ny*h, nz*h
s = h/2
Hdr = 'FoamFile { version 2.0; format ascii; class dictionary; object %s; }\n'
for sub in ('constant', 'system'):
    os.makedirs(os.path.join(d, sub), exist_ok=True)
def w(path, obj, body):
    with open(os.path.join(d, path), 'w') as f:
        f.write('// mpmFoam tutorial mpm/slopeFailure3D, written by makeCase.py\n')
        f.write(Hdr % obj + body)
with open(os.path.join(d, 'meshSize'), 'w') as f:
    f.write(f'-setnumber Lx {Lx} -setnumber Ly {Ly} -setnumber D {D} '
            + (f'-setnumber lc {h:.6g} -setnumber structured 1\n' if a['structured']
               else f'-setnumber lc {a["tet"]*h:.6g} -setnumber structured 0\n'))
w('system/blockMeshDict', 'blockMeshDict', f'''
// {Lx:g} x {Ly:g} x {D:g} m in cubes of h = {h:g} m (for kernel bspline2)
vertices ( (0 0 0) ({Lx} 0 0) ({Lx} {Ly} 0) (0 {Ly} 0)
           (0 0 {D}) ({Lx} 0 {D}) ({Lx} {Ly} {D}) (0 {Ly} {D}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {ny} {nz}) simpleGrading (1 1 1) );
boundary
(
    base  {{ type wall; faces ((0 1 5 4)); }}
    back  {{ type wall; faces ((0 4 7 3)); }}
    sides {{ type wall; faces ((0 3 2 1) (4 5 6 7)); }}
    open  {{ type patch; faces ((1 2 6 5) (3 7 6 2)); }}
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
writePrecision  8;
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
kernel = a['kernel']
support = ('\nsupportSize ' + a['support'] + ';  // h_v of the umls kernel: mean, maxEdge or graded'
           if a['kernel'] == 'umls' else '')
if a['kernel'] == 'umls' and a['support'] == 'ring':
    # mlsRing on the ring reach with the weights' own gradient (no eta)
    kernel = 'mlsRing'
    support = ('\nsupportSize ring;\ngradient    derivative;\n'
               'sampleWeight adaptive;')
w('constant/mpmProperties', 'mpmProperties', f'''
kernel      {kernel};{support}
updateScheme {a["update"]};
transfer    {a["transfer"]};
flipRatio   {a["flip"]:g};
CFL         {a["CFL"]:g};
stepLength  {a["step"]};
gravity     (0 -9.81 0);
logInterval 2000;

// The sensitive clay of dissertation 2.3.4 (Zhao et al. 2023b)
materials
{{
    clay
    {{
        type    henckyJ2;
        rho     2150;
        E       25e6;
        nu      0.499;
        kappaP  40.82e3;
        kappaR  2.45e3;
        eta     5;
        Fbar    on;
    }}
}}

boundary
{{
    base  {{ type fixed; }}     // fixed base
    "back|sides" {{ type slip; }}  // rollers on the three sides
}}
''')
# Particle columns: width s, up to the surface at the column's centre
regions = []
i = 0
while (i + 0.5)*s < toe:
    xc = (i + 0.5)*s
    top = H if xc <= a['crest'] else H - (xc - a['crest'])*math.tan(math.radians(a['beta']))
    if top >= s:
        regions.append((i*s, (i + 1)*s, top))
    i += 1
# merge the crest columns (same top) into one box
boxes = []
for x0, x1, top in regions:
    if boxes and abs(boxes[-1][2] - top) < 1e-12:
        boxes[-1][1] = x1
    else:
        boxes.append([x0, x1, top])
body = '\n'.join(f'''    c{k} {{ type box; min ({b[0]:.6g} 0 0); max ({b[1]:.6g} {b[2]:.6g} {D:g});
          material clay; spacing {s:g}; }}''' for k, b in enumerate(boxes))
w('system/mpmSetParticlesDict', 'mpmSetParticlesDict', f'''
// The slope: H = {H:g} m at {a["beta"]:g} deg, crest {a["crest"]:g} m, toe at x = {toe:.4g} m;
// particle spacing {s:g} m, in columns up to the surface
regions
(
{body}
);
''')
with open(os.path.join(d, 'slope'), 'w') as f:
    f.write(f'H {H}\nbeta {a["beta"]}\ncrest {a["crest"]}\ntoe {toe}\nspacing {s}\ndepth {D}\nkernel {a["kernel"]}\n')
print(f"{d}: {a['kernel']}, H = {H:g} m at {a['beta']:g} deg, toe x = {toe:.3g} m,"
      f" box {Lx:g} x {Ly:g} x {D:g} m, h = {h:g} m, spacing {s:g} m")
