#!/usr/bin/python3
"""Write the koalas over Mach-diamond jets (dissertation 3.3.2, Fig. 3.19,
Table 3.1) into directory D: python3 makeCase.py D [n=64] [tEnd=1.4]
[write=0.1] [M=3] [pRatio=0.5] [E=1e3] [nu=0.22] [rhoS=3] [g=1]
[bottom=0.4] [np=1] [substeps=32]

The box [0, 2] x [0, 1] x [0, 0.5] (y up), 2n x n x n/2 cells of 1/n (n a
multiple of 16; Table 3.1's 256 x 128 x 64 is n = 128), gas rho 1.4, p 1
at rest (sound speed 1).  Three square nozzles of side 1/8 in the floor,
centred at x = 0.375, 1, 1.625 and z = 0.25: inlets blowing upward at Mach
M with pRatio times the ambient pressure at the ambient temperature, as
machDiamond2D's (Fig. 3.18): over-expanded jets.  The rest of the floor
(patch floor) is a wall, for the gas and (separable) for the solids; the
sides and the top (patch open) are outlets for both.  The nozzles are cut
out of the floor by topoSet (system/topoSetDict.nozzle) and createPatch.

Above each nozzle sits an elastic koala (neoHookean, E, nu: Table 3.1's
1e3, 0.22), its feet at y = bottom: a body (an ellipsoid of radii 0.075,
0.09, 0.065), a head (a sphere of radius 0.065) and two ears (spheres of
0.032).  Their densities go 1 : 4 : 9 from left to right (Fig. 3.19),
rhoS times that; gravity g downward acts on the solids.  The koalas'
cells hold 2 x 2 x 2 particles each.  The cell sets are computed here
(blockMesh numbers the cells i + nx (j + ny k); createPatch keeps that
order) and written to constant/cellSets (Allrun copies them to
constant/polyMesh/sets) for topoSet's cellZones.  np > 1 writes a
decomposeParDict for np ranks (simple along x, delta 1e-8: boxes of the
lattice; the middle koala straddles the cut of 2 ranks).
"""
import os, sys
import numpy as np
sys.path.insert(0, os.path.join(os.environ['MPMFOAM_DIR'], 'bin', 'tools'))
from csmpmCase import Case, parameters
a = parameters(dict(n=64, tEnd=1.4, write=0.1, M=3.0, pRatio=0.5,
                    E=1e3, nu=0.22, rhoS=3.0, g=1.0, bottom=0.4, np=1,
                    substeps=32), sys.argv[2:])
d = sys.argv[1]
n = int(a['n'])
if n % 16 or n < 16:
    sys.exit(f'makeCase.py: n must be a positive multiple of 16 (the '
             f'nozzles on cell faces), got {n}')
nx, ny, nz = 2*n, n, n//2
dx = 1.0/n
case = Case(d, ('0', 'constant/cellSets', 'system'))
w = case.write

# The jets: machDiamond2D's inlet state (sound speed 1 at rho 1.4, p 1)
rhoA, pA = 1.4, 1.0
pJ = a['pRatio']*pA
rhoJ = rhoA*a['pRatio']
uJ = a['M']*(1.4*pJ/rhoJ)**0.5
centres = (0.375, 1.0, 1.625)
half, zc = 1/16, 0.25

# The koalas: cell centres inside body, head or ears
k = np.arange(nx*ny*nz)
x = (k % nx + 0.5)*dx
y = ((k//nx) % ny + 0.5)*dx
z = (k//(nx*ny) + 0.5)*dx
names = ('light', 'middle', 'heavy')
ratios = (1, 4, 9)
y0 = a['bottom']
def inEllipsoid(c, r):
    return (((x - c[0])/r[0])**2 + ((y - c[1])/r[1])**2
            + ((z - c[2])/r[2])**2) <= 1
koalas = []
for xc in centres:
    inside = (inEllipsoid((xc, y0 + 0.09, zc), (0.075, 0.09, 0.065))
              | inEllipsoid((xc, y0 + 0.215, zc), (0.065,)*3)
              | inEllipsoid((xc - 0.06, y0 + 0.265, zc), (0.032,)*3)
              | inEllipsoid((xc + 0.06, y0 + 0.265, zc), (0.032,)*3))
    koalas.append(np.nonzero(inside)[0])
for name, cells in zip(names, koalas):
    w(f'constant/cellSets/{name}', 'cellSet', name,
      f'{len(cells)}\n(\n' + '\n'.join(map(str, cells)) + '\n)\n')

w('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices ( (0 0 0) (2 0 0) (2 1 0) (0 1 0) (0 0 0.5) (2 0 0.5) (2 1 0.5) (0 1 0.5) );
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {ny} {nz}) simpleGrading (1 1 1) );
boundary
(
    floor {{ type wall; faces ((0 1 5 4)); }}
    open  {{ type patch; faces ((0 4 7 3) (1 2 6 5) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }}
);
''')
eps = 0.25*dx
boxes = ' '.join(f'({xc - half} {-eps} {zc - half}) ({xc + half} {eps} {zc + half})'
                 for xc in centres)
w('system/topoSetDict.nozzle', 'dictionary', 'topoSetDict', f'''
actions
(
    {{ name nozzle; type faceSet; action new; source boxToFace; boxes ({boxes}); }}
);
''')
w('system/createPatchDict', 'dictionary', 'createPatchDict', '''
pointSync false;
patches ( { name nozzle; patchInfo { type patch; } constructFrom set; set nozzle; } );
''')
w('system/topoSetDict', 'dictionary', 'topoSetDict', 'actions\n(\n' + ''.join(
    f'    {{ name {m}; type cellZoneSet; action new; source setToCellZone; set {m}; }}\n'
    for m in names) + ');\n')

mats = ' '.join(f'{m} {{ type neoHookean; rho {a["rhoS"]*r!r}; E {a["E"]}; nu {a["nu"]}; }}'
                for m, r in zip(names, ratios))
case.common(a['tEnd'], a['write'], 17,
            'order couplingFirst; ghostInit ambient; '
            f'solidSubsteps {a["substeps"]};\n    energyAudit yes;',
            mats,
            f'gravity (0 {-a["g"]!r} 0);\n'
            'boundary { "floor|nozzle" { type separable; } open { type outlet; } }\n',
            boundaries=f'nozzle {{ type inlet; rho {rhoJ!r}; U (0 {uJ!r} 0); p {pJ!r}; }}\n'
                       '    floor { type wall; }\n    open { type outlet; }',
            patches='floor|nozzle|open')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', 'regions\n(\n' + ''.join(
    f'    {m} {{ type cellZone; zone {m}; material {m}; perCell 2; }}\n' for m in names)
    + ');\n')
if a['np'] > 1:
    w('system/decomposeParDict', 'dictionary', 'decomposeParDict', f'''
numberOfSubdomains {a["np"]};
method simple;
coeffs {{ n ({a["np"]} 1 1); delta 1e-8; }}
''')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{nx} {ny} {dx!r} {a["M"]!r} {pJ!r} {rhoJ!r} {uJ!r}\n')
print('machDiamond3D: %d x %d x %d cells, koalas of %s cells, jets Mach %g '
      'at %g m/s' % (nx, ny, nz, ', '.join(str(len(c)) for c in koalas),
                     a['M'], uJ))
