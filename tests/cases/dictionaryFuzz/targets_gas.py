"""Fuzz targets of the gas solver (shockMpmFoam): see fuzz.py for the format."""

# Sod's shock tube of compressible/shockTubeVsRhoCentral at 100 cells to
# t = 0.02 (about 20 steps).  The 0/ files are fuzzed on the uniform state
# (before setFields, which would overwrite them).
UNIFORM = r'''
cp -r "$MPMFOAM_TUTORIALS/compressible/shockTubeVsRhoCentral"/{0,constant,system} .
echo "nCells 100;" > system/meshSettings
sed -i -e 's/^application .*/application shockMpmFoam;/' \
       -e 's/^endTime .*/endTime 0.02;/' -e 's/^writeInterval .*/writeInterval 0.01;/' \
       system/controlDict
blockMesh > log.blockMesh 2>&1
'''
SOD = UNIFORM + "setFields > log.setFields 2>&1\n"

RUN = "shockMpmFoam"
CLEAN = "rm -rf 0.0* log.setFields; foamListTimes -rm > /dev/null 2>&1; true"

TARGETS = [
    {
        "name": "shockMpmFoam-sod",
        "setup": SOD,
        "run": RUN,
        "clean": CLEAN,
        "files": {
            "system/shockMpmDict": None,
            "constant/thermophysicalProperties": None,
        },
        "timeout": 30,
    },
    {
        # the initial fields: a uniform state moving at 0.5
        "name": "shockMpmFoam-uniform",
        "setup": UNIFORM + "sed -i 's/^internalField .*/internalField uniform (0.5 0 0);/' 0/U\n",
        "run": RUN,
        "clean": CLEAN,
        "files": {"0/p": None, "0/T": None, "0/U": None},
        "timeout": 30,
    },
    {
        # the same tube with the semi-implicit stepper and the density given
        # in 0/rho instead of 0/T
        "name": "shockMpmFoam-sod-semiImplicit",
        "setup": UNIFORM + r'''
sed -i 's/^\( *stepper \).*/\1 semiImplicit;/' system/shockMpmDict
rm 0/T
cat > 0/rho <<'RHO'
FoamFile { version 2.0; format ascii; class volScalarField; object rho; }
dimensions      [1 -3 0 0 0 0 0];
internalField   uniform 1;
boundaryField { sides { type zeroGradient; } empty { type empty; } }
RHO
''',
        "run": RUN,
        "clean": CLEAN,
        "files": {"system/shockMpmDict": None, "0/rho": None},
        "timeout": 30,
    },
    {
        # inlet, outlet, walls and the corner treatment: the forward step on
        # its coarse mesh, a few steps
        "name": "shockMpmFoam-forwardStep",
        "setup": r'''
cp -r "$MPMFOAM_TUTORIALS/compressible/forwardStep"/{0,constant,system} .
[ -d 0 ] || cp -r 0.orig 0
sed -i -e 's/^application .*/application shockMpmFoam;/' \
       -e 's/^endTime .*/endTime 0.01;/' -e 's/^writeInterval .*/writeInterval 0.01;/' \
       system/controlDict
blockMesh > log.blockMesh 2>&1
''',
        "run": "shockMpmFoam",
        "clean": CLEAN,
        "files": {
            "system/shockMpmDict": None,
            "0/U": None,
            "0/p": None,
        },
        "timeout": 30,
    },
]
