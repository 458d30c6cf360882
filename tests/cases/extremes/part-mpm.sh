#!/bin/bash
# Extremes, MPM part (umlsMpmFoam, run by ../test in its directory mpm/).
# A 2D plane-strain square body on a 1 x 1 background mesh of 20 x 20 cells
# (h = 0.05), rho 1000, with floating-point traps on (FOAM_SIGFPE=true):
#   nu      Poisson's ratio 0, 0.3, 0.49, 0.4999 (E 1e6), for linearElastic,
#           neoHookean, fixedCorotated;
#   E       Young's modulus 1e2, 1e4, 1e6, 1e9 Pa (neoHookean, nu 0.3);
#   CFL 1   kernels umls (APIC), mlsRing (APIC), linear (FLIP), neoHookean;
#   J 0.05  a body compressed to J = det F = 0.05 (F = diag(0.224, 0.224,
#           1)), 0.1 wide, 144 particles, between slip walls: it expands
#           4.5x (to the walls and back);
#   J 20    a body stretched to J = 20 (F = diag(4.47, 4.47, 1)), 0.4 wide,
#           256 particles, free: it collapses to a fifth of its width;
#           both with neoHookean and fixedCorotated, each with FLIP and
#           APIC (linearElastic is a small-strain model: J = 20 or 0.05
#           make no sense for it).
# The nu, E and CFL bodies (0.4 wide, 256 particles, free) start with
# v_x = 0.01 c sin(2.5 pi x) (c the P-wave speed): 1 % strains, a vibration.
# Every run lasts 10 P-wave transits of 0.4 (t = 4/c) at CFL 0.5 unless
# said otherwise.
#
# Checks, per run:
#  - it ends cleanly: either it runs to its end (exit 0, "End", the end
#    time written) or it stops with a FatalError naming the cause and a
#    last good time whose cloud exists on disk; a signal or the 60 s limit
#    fails;
#  - finite: the conservation history and the last written cloud (U, F,
#    positions) hold no nan/inf;
#  - energy bounded: the total energy (kinetic + strain) stays below
#    1.25 x that of the seeded cloud in a run that ends (the symplectic
#    step's energy error grows with the step: measured at most 2 % at
#    CFL 0.5 and 13.7 % at CFL 1 (linear kernel, in its first step), while
#    an unstable run grows without bound) and below 2 x in one that stops
#    (the solver's own guard stops a run whose energy has doubled);
#  - momentum (free bodies): |p(end) - p(0)| <= 1e-9 sqrt(2 M Kmax) (no
#    external force; measured 1e-12 relative: round-off);
#  - the nu, E and vibrating CFL-0.5 runs must run to their end (they did
#    before these checks; a stop there is a regression).
# And per sweep: the time step follows the wave speed: the first dt times
# c_P (nu sweep) and times sqrt(E) (E sweep) agree to 1e-6 relative (dt =
# CFL h/(c + |v|) with |v| = 0.01 c: exact up to round-off).
. "$MPMFOAM_DIR/tests/cases/caseFunctions"
export FOAM_SIGFPE=true

# The mesh, once
mkdir -p mesh/system mesh/constant
cat > mesh/system/blockMeshDict <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 0.05) (1 0 0.05) (1 1 0.05) (0 1 0.05) );
blocks ( hex (0 1 2 3 4 5 6 7) (20 20 1) simpleGrading (1 1 1) );
boundary
(
    walls { type patch; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
EOF
cp "$MPMFOAM_DIR/tutorials/mpm/vibratingBar/system/fvSchemes" \
   "$MPMFOAM_DIR/tutorials/mpm/vibratingBar/system/fvSolution" mesh/system/
cat > mesh/system/controlDict <<'EOF'
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
libs            ("libmpmFoamFunctionObjects.so");
application     umlsMpmFoam;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         1;
deltaT          1e-6;
writeControl    adjustableRunTime;
writeInterval   1;
writeFormat     ascii;
writePrecision  12;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
functions
{
    conservation { type mpmConservation; libs ("libmpmFoamFunctionObjects.so"); }
}
EOF
( cd mesh && run log.blockMesh blockMesh ) || { fail "blockMesh"; exit 1; }

cat > analyse.py <<'PY'
# analyse.py name rc endTime free mustEnd: the checks of one run (see part-mpm.sh)
import glob, math, os, re, sys
name, rc, tEnd, free, mustEnd = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4] == "1", sys.argv[5] == "1"
log = open(os.path.join(name, "log.umlsMpmFoam"), errors="replace").read()
def out(ok, what):
    print(("PASS: " if ok else "FAIL: ") + name + ": " + what)
times = sorted((float(d), d) for d in os.listdir(name) if re.fullmatch(r"[0-9.e+-]+", d))
last = times[-1][1] if times else None
# 1. outcome
ended = rc == 0 and re.search(r"^End$", log, re.M) and last is not None \
    and abs(float(last) - tEnd) <= 1e-6*tEnd
good = None
if rc == 1 and "FOAM FATAL" in log:
    m = re.search(r"last good state (?:is written|written is) at t = ([0-9.e+-]+)", log)
    good = m.group(1) if m else None
stopped = good is not None and os.path.isfile(os.path.join(name, good, "lagrangian", "mpmCloud", "U"))
if ended:
    out(not mustEnd or ended, "ran to its end (t = %s, exit 0)" % last)
elif stopped:
    cause = re.search(r"FOAM FATAL.*?\n(.{0,90})", log, re.S).group(1).strip()
    out(not mustEnd, "stopped cleanly, last good time %s on disk (%s...)%s"
        % (good, cause, "; it must run to its end" if mustEnd else ""))
else:
    out(False, "neither ran to its end nor stopped cleanly (exit %d, last time %s)" % (rc, last))
# 2. finite
rows = [list(map(float, l.split())) for l in open(glob.glob(os.path.join(name, "postProcessing/conservation/*/conservation.dat"))[0]) if not l.startswith("#") and l.strip()]
fin = all(math.isfinite(x) for r in rows for x in r) and len(rows) > 0
cloud = os.path.join(name, good if stopped else (last or "0"), "lagrangian", "mpmCloud")
bad = [f for f in ("U", "F", "positions") if not os.path.isfile(os.path.join(cloud, f))
       or re.search(r"(?<![A-Za-z])[-+]?(nan|inf)(?![A-Za-z])", open(os.path.join(cloud, f)).read(), re.I)]
out(fin and not bad, "finite (%d steps in the history; last cloud %s)" % (len(rows), "finite" if not bad else "bad: " + " ".join(bad)))
# 3. energy bounded (columns: t mass xCM yCM zCM px py pz Lx Ly Lz kinetic strain grav total),
#    against the energy of the seeded cloud at t = 0 (the history starts after
#    the first step); no gravity here
def field(name_):
    """The values of a cloud field at t = 0 as lists (n(...) or n{v})"""
    txt = open(os.path.join(name, "0", "lagrangian", "mpmCloud", name_)).read()
    txt = txt[txt.index("}", txt.index("FoamFile")) + 1:]
    m = re.search(r"(\d+)\s*([({])", txt)
    n, rest = int(m.group(1)), txt[m.end():]
    if m.group(2) == "{":
        v = rest[:rest.index("}")].strip("() ")
        return [list(map(float, v.split()))]*n
    items = re.findall(r"\(([^()]*)\)", rest)
    if items:
        return [list(map(float, t.split())) for t in items[:n]]
    return [[float(x)] for x in rest[:rest.index(")")].split()[:n]]
if rows:
    U, m, V0, psi = field("U"), field("mass"), field("V0"), field("psi")
    E0 = sum(0.5*mi[0]*(u[0]**2 + u[1]**2 + u[2]**2) for mi, u in zip(m, U)) \
        + sum(v[0]*p[0] for v, p in zip(V0, psi))
    Emax = max(r[14] for r in rows)
    bound = 1.25 if ended else 2.0
    out(fin and Emax <= bound*E0 + 1e-300, "energy bounded: max %.4g <= %.1f x start %.4g (%.4g)" % (Emax, bound, E0, Emax/E0 if E0 else 0))
    # 4. momentum
    if free:
        M = rows[0][1]
        Kmax = max(r[11] for r in rows)
        scale = math.sqrt(2*M*Kmax)
        dp = math.sqrt(sum((rows[-1][i] - rows[0][i])**2 for i in (5, 6, 7)))
        out(fin and dp <= 1e-9*scale, "momentum conserved: |dp| %.3g <= 1e-9 x %.4g" % (dp, scale))
PY

# runCase <name> <walls 0|1> <material> <E> <nu> <CFL> <F or ""> <v amplitude/c>
#         <kernel> <transfer> <mustEnd 0|1> <body: min max spacing>
# prints its checks; its first dt goes to <name>/dt
runCase()
{
    local name=$1 walls=$2 mat=$3 E=$4 nu=$5 cfl=$6 F0=$7 amp=$8 kernel=$9 transfer=${10} mustEnd=${11} body=${12}
    local c tEnd v
    c=$(awk -v E=$E -v nu=$nu 'BEGIN{ printf "%.17g", sqrt(E*(1-nu)/((1+nu)*(1-2*nu))/1000) }')
    tEnd=$(awk -v c=$c 'BEGIN{ printf "%.8g", 4/c }')
    v=$(awk -v c=$c -v a=$amp 'BEGIN{ printf "%.8g", a*c }')
    rm -rf $name && mkdir $name && cp -r mesh/system mesh/constant $name/
    sed -i "s/^endTime .*/endTime $tEnd;/; s/^writeInterval .*/writeInterval $(awk -v t=$tEnd 'BEGIN{ printf "%.8g", t/2 }');/" \
        $name/system/controlDict
    {
        echo 'FoamFile { version 2.0; format ascii; class dictionary; object mpmProperties; }'
        echo "kernel $kernel; transfer $transfer; CFL $cfl; logInterval 1000;"
        echo "materials { body { type $mat; rho 1000; E $E; nu $nu; } }"
        [ "$walls" = 1 ] && echo "boundary { walls { type slip; } }"
    } > $name/constant/mpmProperties
    {
        echo 'FoamFile { version 2.0; format ascii; class dictionary; object mpmSetParticlesDict; }'
        echo "regions ( body { type box; $body material body;"
        [ -n "$F0" ] && echo "F ($F0);"
        echo "velocitySine { amplitude ($v 0 0); wavenumber (7.853981633974483 0 0); } } );"
    } > $name/system/mpmSetParticlesDict
    ( cd $name && run log.mpmSetParticles mpmSetParticles ) \
        || { fail "$name: mpmSetParticles (see $name/log.mpmSetParticles)"; return; }
    ( cd $name && timeout 60 umlsMpmFoam > log.umlsMpmFoam 2>&1 )
    local rc=$?
    python3 analyse.py $name $rc $tEnd $((1 - walls)) $mustEnd
    awk '!/^#/ && NF { print $1; exit }' $name/postProcessing/conservation/*/conservation.dat > $name/dt 2>/dev/null
}

big="min (0.3 0.3 0); max (0.7 0.7 0.05); spacing 0.025;"
small="min (0.45 0.45 0); max (0.55 0.55 0.05); spacing 0.008333333333333333;"
a=$(awk 'BEGIN{ printf "%.17g", sqrt(0.05) }')
b=$(awk 'BEGIN{ printf "%.17g", sqrt(20) }')

# Poisson's ratio
for mat in linearElastic neoHookean fixedCorotated
do
    for nu in 0 0.3 0.49 0.4999
    do
        runCase nu$nu-$mat 0 $mat 1e6 $nu 0.5 "" 0.01 umls APIC 1 "$big"
    done
done
# dt c_P: the same for every nu (neoHookean)
python3 - nu0-neoHookean nu0.3-neoHookean nu0.49-neoHookean nu0.4999-neoHookean <<'PY'
import math, sys
v = []
for d in sys.argv[1:]:
    nu = float(d[2:].split("-")[0])
    c = math.sqrt(1e6*(1 - nu)/((1 + nu)*(1 - 2*nu))/1000)
    v.append(float(open(d + "/dt").read())*c)
spread = (max(v) - min(v))/max(v)
print(("PASS" if spread <= 1e-6 else "FAIL") + ": the time step follows the P-wave speed over nu 0..0.4999:"
      " dt c_P = %s (spread %.2g <= 1e-6)" % (" ".join("%.6g" % x for x in v), spread))
PY

# Young's modulus
for E in 1e2 1e4 1e6 1e9
do
    runCase E$E 0 neoHookean $E 0.3 0.5 "" 0.01 umls APIC 1 "$big"
done
python3 - E1e2 E1e4 E1e6 E1e9 <<'PY'
import math, sys
v = [float(open(d + "/dt").read())*math.sqrt(float(d[1:])) for d in sys.argv[1:]]
spread = (max(v) - min(v))/max(v)
print(("PASS" if spread <= 1e-6 else "FAIL") + ": dt scales like 1/sqrt(E) over E 1e2..1e9:"
      " dt sqrt(E) = %s (spread %.2g <= 1e-6)" % (" ".join("%.6g" % x for x in v), spread))
PY

# CFL 1 (umls stops with the energy guard at this CFL; the others run)
runCase cfl1-umls 0 neoHookean 1e6 0.3 1 "" 0.01 umls APIC 0 "$big"
runCase cfl1-mlsRing 0 neoHookean 1e6 0.3 1 "" 0.01 mlsRing APIC 0 "$big"
runCase cfl1-linear 0 neoHookean 1e6 0.3 1 "" 0.01 linear FLIP 0 "$big"

# Compressed to J = 0.05 (between slip walls) and stretched to J = 20
for mat in neoHookean fixedCorotated
do
    for tr in FLIP APIC
    do
        runCase J0.05-$mat-$tr 1 $mat 1e6 0.3 0.5 "$a 0 0 0 $a 0 0 0 1" 0 umls $tr 0 "$small"
        runCase J20-$mat-$tr 0 $mat 1e6 0.3 0.5 "$b 0 0 0 $b 0 0 0 1" 0 umls $tr 0 "$big"
    done
done
