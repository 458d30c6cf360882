#!/usr/bin/python3
"""Write the 3D shell-burst smoke test (after the pumpkins of the
dissertation's Fig. 3.13) into directory D: python3 makeCase.py D [n=32]
[tEnd=0.06] [write=0.02] [pIn=50] [rhoIn=7] [rhoS=10] [E=500] [nu=0.25]
[rIn=0.2] [rOut=0.27] [material=neoHookean] [yield=20] [residual=-1]
[eta=0] [notch=0]

The unit cube, n^3 cells, `open` (outlets) all round; gas rho 1.4, p 1
outside, hot compressed gas (rhoIn, pIn) inside a spherical shell of radii
rIn and rOut centred at (0.5, 0.5, 0.5), its cells (topoSet: sphereToCell
rOut less sphereToCell rIn) filled with 2 x 2 x 2 particles each;
neoHookean (elastic) or henckyJ2 (plastic, yield stress 'yield': Table
3.1's plastic pumpkin; 'residual' and 'eta': its residual strength, by
default the yield stress, and softening).  'notch' > 0 cuts slots along
the meridians x = 0.5 and y = 0.5 from the outside down to that radius:
through the shell for notch <= rIn (four segments, scored like the 2D
shell's ring).  A smoke test of the coupling in 3D: the coarse lattice
makes the shell two cells thick.
"""
import os, sys
sys.path.insert(0, os.path.join(os.environ['MPMFOAM_DIR'], 'bin', 'tools'))
from csmpmCase import Case, material, parameters
a = parameters(dict(n=32, tEnd=0.06, write=0.02, pIn=50.0, rhoIn=7.0,
                    rhoS=10.0, E=500.0, nu=0.25, rIn=0.2, rOut=0.27,
                    material='neoHookean', residual=-1.0, eta=0.0,
                    notch=0.0, **{'yield': 20.0}), sys.argv[2:])
d = sys.argv[1]
n = int(a['n']); dx = 1.0/n
case = Case(d)
w = case.write
case.unitCube(n)
notches = ''
if a['notch'] > 0:
    # slots along the two meridians x = 0.5 and y = 0.5 (the cells whose
    # centres lie within 0.51 dx of the plane: one cell wide for an odd n,
    # two for an even n), cut from the outside down to radius 'notch'
    # (through the shell if notch <= rIn: four scored segments, as an
    # orange's; the mid-plane z = 0.5 of the pictures crosses all four)
    lo, hi = 0.5 - 0.51*dx, 0.5 + 0.51*dx
    boxes = ' '.join(f'({" ".join(str(lo) if e == c else "-1" for e in range(3))}) '
                     f'({" ".join(str(hi) if e == c else "2" for e in range(3))})'
                     for c in range(2))
    notches = f'''    {{ name notch; type cellSet; action new; source boxToCell;
       boxes ({boxes}); }}
    {{ name notch; type cellSet; action delete; source sphereToCell;
       origin (0.5 0.5 0.5); radius {a["notch"]}; }}
    {{ name shell; type cellSet; action delete; source cellToCell; set notch; }}
'''
w('system/topoSetDict', 'dictionary', 'topoSetDict', f'''
actions
(
    {{ name shell; type cellSet; action new; source sphereToCell;
       origin (0.5 0.5 0.5); radius {a["rOut"]}; }}
    {{ name shell; type cellSet; action delete; source sphereToCell;
       origin (0.5 0.5 0.5); radius {a["rIn"]}; }}
{notches}    {{ name shell; type cellZoneSet; action new; source setToCellZone; set shell; }}
    {{ name hot; type cellSet; action new; source sphereToCell;
       origin (0.5 0.5 0.5); radius {a["rIn"]}; }}
);
''')
w('system/setFieldsDict', 'dictionary', 'setFieldsDict', f'''
defaultFieldValues ( volScalarFieldValue p 1 volScalarFieldValue rho 1.4 );
regions ( cellToCell {{ set hot; fieldValues ( volScalarFieldValue p {a["pIn"]}
    volScalarFieldValue rho {a["rhoIn"]} ); }} );
''')
case.common(a['tEnd'], a['write'], 10,
            'order couplingFirst; ghostInit ambient;',
            f'shell {{ {material(a)} }}')
w('system/mpmSetParticlesDict', 'dictionary', 'mpmSetParticlesDict', '''
regions ( shell { type cellZone; zone shell; material shell; perCell 2; } );
''')
with open(os.path.join(d, 'caseInfo'), 'w') as f:
    f.write(f'{n} {n} {dx!r}\n')
