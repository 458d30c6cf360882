#!/bin/bash
# Extremes, CSMPM part (shockMpmFoam with an MPM solid, run by ../test in its
# directory csmpm/): the lifting-cylinder setup of
# tutorials/csmpm/liftingCylinder (makeCase.py: a Mach 3 shock in a channel
# hits a cylinder resting on the floor; gas rho 1.4, p 1) on a 50 x 10
# lattice to t = 0.05, with floating-point traps on (FOAM_SIGFPE=true), at
# the ends of issue 10's ranges:
#   rho1     solid-to-gas density ratio 1 (rhoS 1.4)
#   rho1e4   density ratio 1e4 (rhoS 1.4e4)
#   E1e2     Young's modulus 1e2 Pa (a solid softer than the gas's pressure)
#   E1e9     Young's modulus 1e9 Pa with maxSteps 2000: the solid's time step
#            (8.9e-7 s) would need 55,904 steps (it runs them in about 50 s
#            when allowed: measured), so the run must stop at once with a
#            message naming the time step and maxSteps, its state written
#   mach9    a Mach 9 shock
# Checks, per run: it ends cleanly (runs to its end: exit 0, "End", the end
# time written with the cloud; or, E1e9, stops with a FatalError naming the
# cause, the last good time written with its cloud), never a signal or the
# 120 s limit; no nan/inf in the last written gas fields and cloud; the
# cloud keeps every particle.  Measured: 0.1-0.7 s per run (41-503 steps).
. "$MPMFOAM_DIR/tests/cases/caseFunctions"
export FOAM_SIGFPE=true
make="$MPMFOAM_DIR/tutorials/csmpm/liftingCylinder/makeCase.py"

# runCase <name> <mustEnd 0|1> <makeCase options ...>
runCase()
{
    local name=$1 mustEnd=$2
    shift 2
    rm -rf "$name"
    python3 "$make" "$name" nx=50 tEnd=0.05 write=0.025 "$@" > /dev/null \
        || { fail "$name: makeCase.py $*"; return; }
    ( cd "$name" && blockMesh > log.blockMesh 2>&1 && mpmSetParticles > log.mpmSetParticles 2>&1 ) \
        || { fail "$name: blockMesh or mpmSetParticles (see $name/)"; return; }
    local n0
    n0=$(sed -n 's/^Wrote \([0-9]*\) particles.*/\1/p' "$name/log.mpmSetParticles")
    ( cd "$name" && timeout 120 shockMpmFoam > log.shockMpmFoam 2>&1 )
    local rc=$?
    local last
    last=$(cd "$name" && ls -d [0-9]* 2>/dev/null | sort -g | tail -n 1)
    if [ "$rc" -ge 124 ]
    then
        fail "$name: killed by a signal or the time limit (exit $rc)"
        return
    fi
    if [ "$mustEnd" = 1 ]
    then
        if [ "$rc" = 0 ] && grep -q '^End' "$name/log.shockMpmFoam" && [ "$last" = 0.05 ]
        then
            pass "$name ($*): runs to its end ($(grep -c '^Step' "$name/log.shockMpmFoam") steps)"
        else
            fail "$name ($*): did not run to its end (exit $rc, last time $last)"
        fi
    else
        if [ "$rc" != 0 ] && grep -q 'FOAM FATAL' "$name/log.shockMpmFoam" \
            && grep -q "time step" "$name/log.shockMpmFoam" && grep -q maxSteps "$name/log.shockMpmFoam" \
            && grep -q "is written" "$name/log.shockMpmFoam"
        then
            pass "$name ($*): stops at once naming the solid's time step and maxSteps, state at $last written"
        else
            fail "$name ($*): expected a clean stop naming the time step and maxSteps (exit $rc)"
        fi
    fi
    local cloud="$name/$last/lagrangian/mpmCloud"
    if [ -f "$cloud/positions" ] && [ -f "$name/$last/rho" ] && [ -f "$name/$last/p" ]
    then
        if grep -qiE '(^|[^a-z])(nan|-?inf)([^a-z]|$)' "$name/$last/rho" "$name/$last/p" "$name/$last/U" \
            "$cloud"/positions "$cloud"/U "$cloud"/F 2>/dev/null
        then
            fail "$name: non-finite values in the fields or cloud at $last"
        else
            pass "$name: gas fields and cloud at $last finite"
        fi
        local n1
        n1=$(sed -n '/^[0-9][0-9]*$/{p;q}' "$cloud/positions")
        check "$name: particles kept" "$n1" "==" "$n0"
    else
        fail "$name: no cloud or gas fields written at $last"
    fi
}

runCase rho1 1 rhoS=1.4
runCase rho1e4 1 rhoS=14000
runCase E1e2 1 E=100
runCase E1e9 0 E=1e9 maxSteps=2000
runCase mach9 1 M=9
