"""Fuzz targets of BSMS-GNN (bsmsTrain, the bsmsSurrogate function object) and
of the METIS decomposition method (metisCoeffs): see fuzz.py for the format."""

# OpenFOAM's icoFoam cavity (20 x 20), recorded every 5 steps to t = 0.25 at
# two lid speeds (as tests/cases/bsmsTrain)
CAVITY = r'''
tut="$FOAM_TUTORIALS/incompressible/icoFoam/cavity/cavity"
for c in cavity cavity2
do
    cp -r "$tut" $c
    foamDictionary -entry endTime -set 0.25 $c/system/controlDict > /dev/null
    foamDictionary -entry writeInterval -set 5 $c/system/controlDict > /dev/null
    ( cd $c && blockMesh > log.blockMesh 2>&1 && icoFoam > log.icoFoam 2>&1 ) || exit 1
done
foamDictionary -entry boundaryField.movingWall.value -set "uniform (2 0 0)" cavity2/0/U > /dev/null
( cd cavity2 && foamListTimes -rm > /dev/null && icoFoam > log.icoFoam 2>&1 ) || exit 1
cat > cavity/system/bsmsTrainDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object bsmsTrainDict; }
cases        ("." "../cavity2");
inputFields  (U p);
outputFields (U p);
model        bsms;
latent       8;
hidden       8;
levels       { seeding closeCenter; minNodes 20; }
steps        4;
startTime    0.05;
batch        4;
lr           3e-3;
lrMin        1e-5;
lrDecay      0.1;
decaySteps   100;
noise        0.01;
seed         1;
printInterval 2;
checkpointInterval 2;
maxTrainTime 10;
validation   { cases ("../cavity2"); interval 4; }
DICT
'''

TARGETS = [
    {
        "name": "bsmsTrain-cavity",
        "setup": CAVITY,
        "run": "cd cavity && bsmsTrain -fresh",
        "clean": "rm -rf cavity/constant/bsmsModel* cavity/postProcessing",
        "files": {"cavity/system/bsmsTrainDict": None},
        "timeout": 60,
    },
    {
        # the trained model rolled out beside icoFoam from t = 0.05 to 0.1
        "name": "bsmsSurrogate-cavity",
        "setup": CAVITY + r'''
( cd cavity && bsmsTrain > log.bsmsTrain 2>&1 ) || exit 1
cd cavity
foamDictionary -entry startFrom -set startTime system/controlDict > /dev/null
foamDictionary -entry startTime -set 0.05 system/controlDict > /dev/null
foamDictionary -entry endTime -set 0.1 system/controlDict > /dev/null
cat >> system/controlDict <<'FO'
functions
{
    surrogate
    {
        type        bsmsSurrogate;
        libs        ("libmpmFoamGNNSurrogate.so");
        model       "constant/bsmsModel.pt";
        startTime   0.05;
    }
}
FO
''',
        "run": "cd cavity && icoFoam",
        "clean": "cd cavity && rm -rf postProcessing 0.06* 0.07* 0.08* 0.09* 0.1",
        "files": {"cavity/system/controlDict": ["functions/"]},
        "timeout": 60,
    },
    {
        # decomposePar of the cavity into 4 with our METIS method
        "name": "decomposePar-metis",
        "setup": r'''
cp -r "$FOAM_TUTORIALS/incompressible/icoFoam/cavity/cavity"/{0,constant,system} .
blockMesh > log.blockMesh 2>&1 || exit 1
sed -i 's/^application .*/libs ("libmpmFoamDecomposition.so");\napplication icoFoam;/' system/controlDict
cat > system/decomposeParDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 4;
method             metis;
metisCoeffs
{
    method           k-way;
    objective        cut;
    ufactor          30;
    niter            10;
    ncuts            1;
    seed             1;
    contiguous       false;
    minimizeConnectivity false;
    processorWeights (1 1 1 1);
}
DICT
''',
        "run": "decomposePar -force",
        "clean": "rm -rf processor*",
        "files": {"system/decomposeParDict": None},
        # read by OpenFOAM's decomposePar itself (decompositionMethod::New):
        # its "Unknown decompositionMethod type <value>" names the value
        "foreign": ["method"],
        "timeout": 30,
    },
]
