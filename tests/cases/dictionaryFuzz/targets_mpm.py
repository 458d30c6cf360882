"""Fuzz targets of the MPM solver (mpmSetParticles + umlsMpmFoam) and of its
function objects (mpmConservation, mpmParticleProbe, spectrum): see fuzz.py."""

CLEAN = "foamListTimes -rm > /dev/null 2>&1; rm -rf postProcessing 0/lagrangian; true"

TARGETS = [
    {
        # mpm/vibratingBar, 1D, 60 cells, to t = 1 s (about 100 steps),
        # with its mpmConservation and spectrum function objects
        "name": "umlsMpmFoam-vibratingBar",
        "setup": r'''
cp -r "$MPMFOAM_TUTORIALS/mpm/vibratingBar"/{constant,system} .
echo "nCells 60;" > system/meshSettings
sed -i -e 's/^endTime .*/endTime 1;/' -e 's/^writeInterval .*/writeInterval 0.5;/' system/controlDict
blockMesh > log.blockMesh 2>&1
''',
        "run": "mpmSetParticles > log.mpmSetParticles 2>&1 || { cat log.mpmSetParticles; exit 1; }; umlsMpmFoam",
        "clean": CLEAN,
        "files": {
            "constant/mpmProperties": None,
            "system/mpmSetParticlesDict": None,
            "system/controlDict": ["functions/"],
        },
        "timeout": 30,
    },
    {
        # mpm/collidingDisks on a coarse gmsh mesh (lc 0.1), a few steps,
        # with its mpmConservation and mpmParticleProbe function objects
        "name": "umlsMpmFoam-collidingDisks",
        "setup": r'''
src="$MPMFOAM_TUTORIALS/mpm/collidingDisks"
cp -r "$src"/{constant,system} "$src"/*.geo .
gmsh -3 -format msh2 -setnumber lc 0.1 collidingDisks.geo -o disks.msh > log.gmsh 2>&1
gmshToFoam disks.msh > log.gmshToFoam 2>&1
foamDictionary constant/polyMesh/boundary -entry entry0/frontAndBack/type -set empty > /dev/null
sed -i -e 's/^endTime .*/endTime 0.05;/' -e 's/^writeInterval .*/writeInterval 0.05;/' \
       -e 's/^startFrom .*/startFrom startTime;/' system/controlDict
''',
        "run": "mpmSetParticles > log.mpmSetParticles 2>&1 || { cat log.mpmSetParticles; exit 1; }; umlsMpmFoam",
        "clean": CLEAN,
        "files": {
            "constant/mpmProperties": None,
            "system/mpmSetParticlesDict": None,
            "system/controlDict": ["functions/"],
        },
        "timeout": 30,
    },
]
