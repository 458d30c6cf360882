"""More fuzz targets of the gas solver, for tests/cases/dictionaryFuzz/fuzz.py
(same format as its targets_gas.py, which covers the shipped tutorials'
entries only):

    fuzz.py -j 1 -out DIR $MPMFOAM_DIR/tests/cases/dictionaryFuzz/targets_gasExtra.py

  extra-explicit       every optional entry of shockMpmDict written out
                       (variables, maxDeltaT, maxRetries, schlierenScale,
                       cornerTreatment, cornerResetCells, CG*, an outlet
                       with attenuation and farField) and the direct form of
                       thermophysicalProperties (gamma, R)
  extra-semiImplicit   the semi-implicit stepper's CGtolerance, CGmaxIter
  extra-inlet          an inlet with its own rho, U, p (forwardStep), 0/T
  riemannCompare       riemannCompareDict and the gas of the Sod case

Measured (2 cores, -j 1, 44 s): 392 runs, classes ok 65, named 327,
nothing else (ok: entries the run does not use, e.g. CG* of the explicit
stepper, or valid values such as U (1 2 3) or maxRetries 0)."""

UNIFORM = r'''
cp -r "$MPMFOAM_TUTORIALS/compressible/shockTubeVsRhoCentral"/{0,constant,system} .
echo "nCells 100;" > system/meshSettings
sed -i -e 's/^application .*/application shockMpmFoam;/' \
       -e 's/^endTime .*/endTime 0.02;/' -e 's/^writeInterval .*/writeInterval 0.01;/' \
       system/controlDict
blockMesh > log.blockMesh 2>&1
cat > constant/thermophysicalProperties <<'TP'
FoamFile { version 2.0; format ascii; class dictionary; object thermophysicalProperties; }
gamma 1.4;
R 1;
TP
'''
SOD = UNIFORM + "setFields > log.setFields 2>&1\n"
ALL = r'''
cat > system/shockMpmDict <<'D'
FoamFile { version 2.0; format ascii; class dictionary; object shockMpmDict; }
gas
{
    stepper         STEPPER;
    scheme          WENO5;
    variables       characteristic;
    timeIntegration RK3;
    CFL             0.5;
    maxDeltaT       1;
    maxRetries      5;
    schlierenScale  15;
    cornerTreatment entropyTransfer;
    cornerResetCells 3;
    CGtolerance     1e-10;
    CGmaxIter       1000;
}
boundaries
{
    sides
    {
        type outlet;
        attenuation 0.1;
        farField { rho 0.125; U (0 0 0); p 0.1; }
    }
}
D
'''
RUN = "shockMpmFoam"
CLEAN = "rm -rf 0.0* log.setFields; foamListTimes -rm > /dev/null 2>&1; true"

RC_SETUP = r'''
cp -r "$MPMFOAM_TUTORIALS/compressible/shockTubeVsRhoCentral"/{0,constant,system} .
echo "nCells 100;" > system/meshSettings
sed -i -e 's/^application .*/application shockMpmFoam;/' system/controlDict
blockMesh > log.blockMesh 2>&1 && setFields > log.setFields 2>&1 && shockMpmFoam > log.shockMpmFoam 2>&1
'''

TARGETS = [
    {"name": "extra-explicit", "setup": SOD + ALL.replace("STEPPER", "explicit"),
     "run": RUN, "clean": CLEAN,
     "files": {"system/shockMpmDict": None, "constant/thermophysicalProperties": None},
     "timeout": 30},
    {"name": "extra-semiImplicit", "setup": SOD + ALL.replace("STEPPER", "semiImplicit"),
     "run": RUN, "clean": CLEAN,
     "files": {"system/shockMpmDict": ["gas/CG", "gas/CFL", "gas/maxDeltaT"]},
     "timeout": 30},
    {"name": "extra-inlet",
     "setup": r'''
cp -r "$MPMFOAM_TUTORIALS/compressible/forwardStep"/{0,constant,system} .
[ -d 0 ] || cp -r 0.orig 0
sed -i -e 's/^application .*/application shockMpmFoam;/' \
       -e 's/^endTime .*/endTime 0.01;/' -e 's/^writeInterval .*/writeInterval 0.01;/' \
       system/controlDict
sed -i 's/inlet  { type inlet; }.*/inlet { type inlet; rho 1.4; U (3 0 0); p 1; }/' system/shockMpmDict
blockMesh > log.blockMesh 2>&1
''',
     "run": RUN, "clean": CLEAN,
     "files": {"system/shockMpmDict": ["boundaries"], "0/T": None},
     "timeout": 30},
    {"name": "riemannCompare", "setup": RC_SETUP, "run": "riemannCompare -latestTime",
     "clean": "rm -rf postProcessing",
     "files": {"system/riemannCompareDict": None,
               "constant/thermophysicalProperties": ["mixture/specie", "mixture/thermo"]},
     "timeout": 30},
]
