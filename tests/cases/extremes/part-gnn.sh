#!/bin/bash
# Extremes, GNN part: a trained BSMS-GNN fed states far outside its
# training range (run by ../test in its directory gnn/).
#
# The model: OpenFOAM's icoFoam cavity (20 x 20 cells) recorded every 5
# steps to t = 0.25 at lid speeds 1 and 2 (as tests/cases/bsmsTrain),
# BSMS-GNN of latent 16 trained 300 steps on (U p) from t = 0.05 (about
# 11 s).  bsmsTrain records the training range of every state component in
# the model dictionary (U_x in [-0.41, 1.71] here).  Then, with floating-
# point traps on (FOAM_SIGFPE=true: an overflow would be a SIGFPE):
#   bsmsFoam from the lid-2 case's t = 0.05 state (in range): no range
#     warning, runs its 8 model steps, finite fields;
#   bsmsFoam from that state with U x 10 (U_x up to 17): a warning naming
#     U, its value, its cell and its distance beyond the training range in
#     standard deviations of the training inputs (45.7), which must exceed
#     the default threshold of 2; the run goes on to its end with finite
#     fields;
#   bsmsFoam from U = 1e39 (finite, beyond single precision, which the
#     network computes in): the range warning, then a non-finite
#     prediction in the first step stops the run with exit status 1 and a
#     message saying the last good state is the start time, whose U is
#     left unchanged (md5) and no later time is written;
#   bsmsSurrogate beside icoFoam on the lid-2 case from t = 0.05 to 0.15:
#     no range warning, RMSE lines finite;
#   bsmsSurrogate beside scalarTransportFoam (which keeps U as given and
#     transports T in it) from U = 1e39: the range warning names U, the
#     non-finite prediction stops the rollout with a warning, the solver
#     goes on to its end (exit 0, t = 0.15 written) and the surrogate's
#     .dat file records the stop.
# No run may end with a signal; each has a 120 s limit (a hang fails).
. "$MPMFOAM_DIR/tests/cases/caseFunctions"
export FOAM_SIGFPE=true

tut="$FOAM_TUTORIALS/incompressible/icoFoam/cavity/cavity"
[ -d "$tut" ] || tut=/opt/openfoam-v1912/tutorials/incompressible/icoFoam/cavity/cavity

# lim <log> <command...>: run with a 120 s limit; prints the exit status
lim() { local log="$1"; shift; timeout 120 "$@" > "$log" 2>&1; echo $?; }

# record <dir> <lid speed>
record()
{
    rm -rf "$1" && cp -r "$tut" "$1" || return 1
    (
        cd "$1" || exit 1
        foamDictionary -entry endTime -set 0.25 system/controlDict > /dev/null
        foamDictionary -entry writeInterval -set 5 system/controlDict > /dev/null
        foamDictionary -entry boundaryField.movingWall.value \
            -set "uniform ($2 0 0)" 0/U > /dev/null
        run log.blockMesh blockMesh && run log.icoFoam icoFoam
    )
}
record cavity 1 && record cavity2 2 || { fail "cavity recordings (icoFoam)"; exit 1; }

cat > cavity/system/bsmsTrainDict <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object bsmsTrainDict; }
cases        ("." "../cavity2");
inputFields  (U p);
outputFields (U p);
model        bsms;
latent       16;
hidden       16;
levels       { seeding closeCenter; minNodes 20; }
steps        300;
startTime    0.05;
batch        4;
lr           3e-3;
lrMin        1e-5;
lrDecay      0.1;
decaySteps   300;
noise        1e-4;
normAccumulations 50;
seed         1;
printInterval 50;
DICT
status=$(cd cavity && lim log.bsmsTrain bsmsTrain)
check "bsmsTrain of the model exits with 0" "$status" "==" 0
nRange=$(foamDictionary -entry inputMax -value cavity/constant/bsmsModelDict 2>/dev/null \
    | tr -d '()' | wc -w)
# 4 state components: U (3, U_z unused but recorded) and p; "4(" counts one
check "the model dictionary records the training range (4 components + size)" "$nRange" "==" 5
[ -f cavity/constant/bsmsModel.pt ] || { fail "no trained model"; exit 1; }

# from <dir>: the lid-2 case at t = 0.05 with the model, for a rollout
from()
{
    rm -rf "$1" && mkdir "$1" || return 1
    cp -r cavity2/constant cavity2/system cavity2/0.05 "$1"/
    cp cavity/constant/bsmsModel.pt cavity/constant/bsmsModelDict "$1"/constant/
    foamDictionary -entry startFrom -set startTime "$1"/system/controlDict > /dev/null
    foamDictionary -entry startTime -set 0.05 "$1"/system/controlDict > /dev/null
}

# finiteField <file>: 1 if the field file holds no nan/inf
finiteField()
{
    [ -f "$1" ] || { echo 0; return; }
    grep -qiE '(^|[ (])[-+]?(nan|inf)' "$1" && echo 0 || echo 1
}

# distance <log>: the first "lies X standard deviations" of a range warning
distance() { sed -n 's/.* lies \([^ ]*\) standard deviations beyond.*/\1/p' "$1" | head -n 1; }

# A bsmsFoam case writes every model step (writeControl timeStep)
fromBsmsFoam()
{
    from "$1" && foamDictionary -entry writeInterval -set 1 "$1"/system/controlDict > /dev/null
}

# 1. bsmsFoam in range
fromBsmsFoam inRange
status=$(cd inRange && lim log.bsmsFoam bsmsFoam)
check "bsmsFoam in range: exit status" "$status" "==" 0
check "bsmsFoam in range: no range warning" \
    "$(grep -c "outside the model's training range" inRange/log.bsmsFoam)" "==" 0
check "bsmsFoam in range: U at t = 0.25 written and finite" "$(finiteField inRange/0.25/U)" "==" 1

# 2. bsmsFoam from U x 10
fromBsmsFoam far
python3 - far/0.05/U <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
i, j = s.index("internalField"), s.index("boundaryField")
vec = re.compile(r"\(([-0-9.e+]+) ([-0-9.e+]+) ([-0-9.e+]+)\)")
scaled = vec.sub(lambda m: "(%s)" % " ".join(repr(10*float(x)) for x in m.groups()), s[i:j])
open(p, "w").write(s[:i] + scaled + s[j:])
PY
status=$(cd far && lim log.bsmsFoam bsmsFoam)
check "bsmsFoam from U x 10: exit status (runs on)" "$status" "==" 0
log=far/log.bsmsFoam
check "bsmsFoam from U x 10: a range warning names U" \
    "$(grep -c "the input field U is outside the model's training range" $log)" "==" 1
check "bsmsFoam from U x 10: no range warning for p (p is in range)" \
    "$(grep -c "the input field p is outside" $log)" "==" 0
# 45.7 measured: U_x 16.96 is 15.3 beyond 1.71 with std 0.334
check "bsmsFoam from U x 10: distance beyond the range [std] > the threshold 2" "$(distance $log)" ">" 2
check "bsmsFoam from U x 10: the warning gives the training range" \
    "$(grep -c "beyond the training range \[-0.4.*, 1.7.*\] of U_x" $log)" "==" 1
check "bsmsFoam from U x 10: U at t = 0.25 written and finite" "$(finiteField far/0.25/U)" "==" 1

# 3. bsmsFoam from U = 1e39
fromBsmsFoam huge
foamDictionary -entry internalField -set "uniform (1e39 0 0)" huge/0.05/U > /dev/null
sum0=$(md5sum < huge/0.05/U)
status=$(cd huge && lim log.bsmsFoam bsmsFoam)
log=huge/log.bsmsFoam
check "bsmsFoam from U = 1e39: exit status 1 (a FatalError, not a signal)" "$status" "==" 1
check "bsmsFoam from U = 1e39: the range warning names U" \
    "$(grep -c "the input field U is outside the model's training range" $log)" "==" 1
check "bsmsFoam from U = 1e39: FatalError on the non-finite prediction" \
    "$(grep -A1 'FOAM FATAL ERROR' $log | grep -c 'predicted non-finite values at t = 0.075')" "==" 1
check "bsmsFoam from U = 1e39: the message names the last good state (the start time)" \
    "$(grep -c 'the last good state is the start time t = 0.05' $log)" "==" 1
check "bsmsFoam from U = 1e39: the start time's U is left unchanged" \
    "$([ "$(md5sum < huge/0.05/U)" = "$sum0" ] && echo 1 || echo 0)" "==" 1
check "bsmsFoam from U = 1e39: no later time written" "$(ls -d huge/0.0[6-9]* huge/0.[1-9]* 2>/dev/null | wc -l)" "==" 0

# 4. bsmsSurrogate beside icoFoam, in range
from surIco
foamDictionary -entry endTime -set 0.15 surIco/system/controlDict > /dev/null
cat >> surIco/system/controlDict <<'FO'
functions
{
    surrogate { type bsmsSurrogate; libs ("libmpmFoamGNNSurrogate.so"); model "constant/bsmsModel.pt"; }
}
FO
status=$(cd surIco && lim log.icoFoam icoFoam)
check "bsmsSurrogate beside icoFoam in range: exit status" "$status" "==" 0
check "bsmsSurrogate beside icoFoam in range: no range warning" \
    "$(grep -c "outside the model's training range" surIco/log.icoFoam)" "==" 0
dat=$(ls surIco/postProcessing/surrogate/*/bsmsSurrogate.dat 2>/dev/null | head -n 1)
nLines=$(grep -v '^#' "$dat" 2>/dev/null | awk 'NF >= 4 && $3+0 == $3 && $4+0 == $4' | wc -l)
check "bsmsSurrogate beside icoFoam in range: 4 model steps with finite RMSE" "$nLines" "==" 4

# 5. bsmsSurrogate beside scalarTransportFoam from U = 1e39
from surTransport
c=surTransport
foamDictionary -entry internalField -set "uniform (1e39 0 0)" $c/0.05/U > /dev/null
cat > $c/0.05/T <<'EOF'
FoamFile { version 2.0; format ascii; class volScalarField; object T; }
dimensions [0 0 0 1 0 0 0];
internalField uniform 0;
boundaryField
{
    movingWall { type fixedValue; value uniform 1; }
    fixedWalls { type zeroGradient; }
    frontAndBack { type empty; }
}
EOF
cat > $c/constant/transportProperties <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object transportProperties; }
DT DT [0 2 -1 0 0 0 0] 0.01;
EOF
foamDictionary -entry "divSchemes.div(phi,T)" -add "Gauss upwind" $c/system/fvSchemes > /dev/null
foamDictionary -entry solvers.T -add "{ solver PBiCGStab; preconditioner DILU; tolerance 1e-6; relTol 0; }" \
    $c/system/fvSolution > /dev/null
foamDictionary -entry SIMPLE -add "{ nNonOrthogonalCorrectors 0; }" $c/system/fvSolution > /dev/null
foamDictionary -entry application -set scalarTransportFoam $c/system/controlDict > /dev/null
foamDictionary -entry endTime -set 0.15 $c/system/controlDict > /dev/null
# readFields registers p (which scalarTransportFoam does not read) for the model
cat >> $c/system/controlDict <<'FO'
functions
{
    readP { type readFields; libs ("libfieldFunctionObjects.so"); fields (p); }
    surrogate { type bsmsSurrogate; libs ("libmpmFoamGNNSurrogate.so"); model "constant/bsmsModel.pt"; }
}
FO
status=$(cd $c && lim log.scalarTransportFoam scalarTransportFoam)
log=$c/log.scalarTransportFoam
check "bsmsSurrogate from U = 1e39: the solver runs to its end (exit status)" "$status" "==" 0
check "bsmsSurrogate from U = 1e39: the solver's log ends with End" "$(tail -n 3 $log | grep -c '^End')" "==" 1
check "bsmsSurrogate from U = 1e39: T at t = 0.15 written and finite" "$(finiteField $c/0.15/T)" "==" 1
check "bsmsSurrogate from U = 1e39: the range warning names U" \
    "$(grep -c "the input field U is outside the model's training range" $log)" "==" 1
check "bsmsSurrogate from U = 1e39: a warning stops the rollout at the non-finite prediction" \
    "$(grep -c 'predicted non-finite values at t = 0.075 (model step 1); the rollout stops' $log)" "==" 1
dat=$(ls $c/postProcessing/surrogate/*/bsmsSurrogate.dat 2>/dev/null | head -n 1)
check "bsmsSurrogate from U = 1e39: the .dat file records the stop" \
    "$(grep -c '^# non-finite prediction at t = 0.075' "$dat" 2>/dev/null)" "==" 1
