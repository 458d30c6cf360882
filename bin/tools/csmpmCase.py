#!/usr/bin/python3
"""What the 3D CSMPM tutorials' scripts share (csmpm/shellBurst3D,
csmpm/pumpkin3D): writing a case in the unit cube with outlets all round,
and reading a written cloud field.  Imported by those scripts after
sys.path.insert(0, os.path.join(os.environ['MPMFOAM_DIR'], 'bin/tools')).

    parameters(defaults, argv)   key=value arguments over the defaults
                                 (an unknown key stops naming the allowed)
    Case(d)                      case directory d: .write(path, cls, obj,
                                 body) with the FoamFile header
    Case.unitCube(n)             blockMeshDict: n^3 cells, patch `open`
    Case.common(tEnd, write, precision, coupling, materials, mpm='',
                boundaries='open { type outlet; }', patches='open')
                                 controlDict, fvSchemes, fvSolution,
                                 shockMpmDict (semi-implicit WENO5 RK3,
                                 CFL 0.5, the gas's boundaries given
                                 (outlets); the coupling entries
                                 given), thermophysicalProperties (gamma
                                 1.4, R 1), mpmProperties (bspline2, APIC;
                                 the materials given; mpm: more lines of
                                 it), 0/p, 0/rho, 0/U
                                 (1, 1.4, at rest; zeroGradient on
                                 the patches that 'patches', a name or
                                 a regular expression, matches)
    material(a)                  the material dictionary's entries from
                                 a's material, rhoS, E, nu (henckyJ2: yield,
                                 residual (< 0: the yield), eta)
    cloudField(case, t, name)    a cloud field of time t: N x 3 for
                                 vectors (positions: the Cartesian part),
                                 N for scalars, empty if not written
    runFacts(case)               from log.shockMpmFoam and log.wallTime:
                                 ranks, steps, halved (the gas's halved
                                 steps), wall (text), energy (the energy
                                 audit's total, text; 'nan' without one)
    lastFragments(solidDat)      fragments and strays at the last time of
                                 plotCsmpm.py's NAME_solid.dat (text)
"""
import os, re, sys
import numpy as np

HEADER = 'FoamFile { version 2.0; format ascii; class %s; object %s; }\n'
NUM = r'[-+]?\d+\.?\d*(?:[eE][-+]?\d+)?'


def parameters(defaults, argv):
    a = dict(defaults)
    for kv in argv:
        k, v = kv.split('=')
        if k not in a:
            sys.exit(f'makeCase.py: unknown parameter {k} '
                     f'(allowed: {", ".join(sorted(a))})')
        a[k] = type(a[k])(v)
    return a


class Case:
    def __init__(self, d, subdirs=('0', 'constant', 'system')):
        self.d = d
        for sub in subdirs:
            os.makedirs(os.path.join(d, sub), exist_ok=True)

    def write(self, path, cls, obj, body):
        with open(os.path.join(self.d, path), 'w') as f:
            f.write(HEADER % (cls, obj) + body)

    def unitCube(self, n):
        self.write('system/blockMeshDict', 'dictionary', 'blockMeshDict', f'''
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1) );
blocks ( hex (0 1 2 3 4 5 6 7) ({n} {n} {n}) simpleGrading (1 1 1) );
boundary
(
    open {{ type patch; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)
                              (0 3 2 1) (4 5 6 7)); }}
);
''')

    def common(self, tEnd, write, precision, coupling, materials, mpm='',
               boundaries='open { type outlet; }', patches='open'):
        w = self.write
        w('system/controlDict', 'dictionary', 'controlDict', f'''
application shockMpmFoam; startFrom latestTime; startTime 0; stopAt endTime;
endTime {tEnd}; deltaT 1e-6; writeControl adjustable;
writeInterval {write}; purgeWrite 0; writeFormat ascii;
writePrecision {precision}; writeCompression off; timeFormat general;
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
boundaries {{ {boundaries} }}
coupling {{ {coupling} }}
''')
        w('constant/thermophysicalProperties', 'dictionary',
          'thermophysicalProperties', 'gamma 1.4; R 1;\n')
        w('constant/mpmProperties', 'dictionary', 'mpmProperties', f'''
kernel bspline2; transfer APIC; CFL 0.5;
materials {{ {materials} }}
{mpm}''')
        key = patches if patches.isidentifier() else f'"{patches}"'
        for name, cls, dim, val in (
                ('p', 'volScalarField', '[1 -1 -2 0 0 0 0]', 'uniform 1'),
                ('rho', 'volScalarField', '[1 -3 0 0 0 0 0]', 'uniform 1.4'),
                ('U', 'volVectorField', '[0 1 -1 0 0 0 0]', 'uniform (0 0 0)')):
            w('0/' + name, cls, name, f'dimensions {dim};\ninternalField {val};\n'
              f'boundaryField {{ {key} {{ type zeroGradient; }} }}\n')


def material(a):
    mat = f'type {a["material"]}; rho {a["rhoS"]}; E {a["E"]}; nu {a["nu"]};'
    if a['material'] == 'henckyJ2':
        kr = a['yield'] if a['residual'] < 0 else a['residual']
        mat += f' kappaP {a["yield"]}; kappaR {kr}; eta {a["eta"]};'
    return mat


def cloudField(case, t, name):
    p = f'{case}/{t}/lagrangian/mpmCloud/{name}'
    if not os.path.exists(p):
        return np.zeros((0, 3))
    s = open(p).read()
    s = s[s.index('}') + 1:]
    v = re.findall(rf'\(({NUM}) ({NUM}) ({NUM})\)', s)
    m = re.search(rf'^\s*(\d+)\s*\{{', s, re.M)
    if v and m:                             # a uniform list: N{(a b c)}
        return np.tile([float(c) for c in v[0]], (int(m.group(1)), 1))
    if v:
        return np.array([[float(c) for c in m] for m in v])
    m = re.search(rf'(\d+)\s*\{{\s*({NUM})\s*\}}', s)
    if m:                                   # a uniform list: N{value}
        return np.full(int(m.group(1)), float(m.group(2)))
    body = s[s.index('(') + 1:]
    return np.array([float(c) for c in body.split(')')[0].split()])


def runFacts(case):
    log = open(f'{case}/log.shockMpmFoam').read()
    m = re.search(r'^nProcs\s*:\s*(\d+)', log, re.M)
    h = re.search(r'halved steps (\d+)', log)
    audits = re.findall(r'total (' + NUM + ')',
                        log.split('CSMPM energy audit')[-1]) \
        if 'CSMPM energy audit' in log else []
    return dict(ranks=int(m.group(1)) if m else 1,
                steps=len(re.findall(r'^Step ', log, re.M)),
                halved=int(h.group(1)) if h else 0,
                wall=open(f'{case}/log.wallTime').read().strip(),
                energy=audits[0] if audits else 'nan')


def lastFragments(solidDat):
    rows = [l.split() for l in open(solidDat) if l[0] not in '# ' and l.strip()]
    return rows[-1][1], rows[-1][8]
