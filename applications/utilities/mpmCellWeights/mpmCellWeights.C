/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Application
    mpmCellWeights

Group
    mpmFoam utilities

Description
    Writes the cell weights of a particle-weighted decomposition: the
    volScalarField <name> (default particleWeight) of the start time holds,
    per cell, emptyWeight + the number of material points of the MPM cloud
    in the cell.  decomposePar reads it through the decomposeParDict entry
    weightField, so that the ranks hold equal particle counts where the
    material fills only a small part of the mesh (an MPM step costs per
    particle; an empty cell costs almost nothing).  The METIS method of
    libmpmFoamDecomposition ("metis") takes weights (its recursive bisection,
    metisCoeffs { method recursive; }, balances particles best: 7.5 % on the
    mpmBalance test where k-way gives 12 %); OpenFOAM's simple and
    hierarchical methods ignore them.

    The log gives the particles, the cells holding any, and the fraction of
    the mesh they fill.

Usage
    \verbatim
        mpmSetParticles
        mpmCellWeights [-cloud mpmCloud] [-name particleWeight]
                       [-emptyWeight 0.01]
        decomposePar
    \endverbatim
    system/decomposeParDict:
    \verbatim
        numberOfSubdomains  4;
        method              metis;
        weightField         particleWeight;
        metisCoeffs         { method recursive; }
    \endverbatim
    (and libs ("libmpmFoamDecomposition.so") in system/controlDict).

    \table
        Option      | Description                              | Default
        -cloud      | the MPM cloud                            | mpmCloudName of constant/mpmProperties, else mpmCloud
        -name       | name of the weight field written         | particleWeight
        -emptyWeight| weight of a cell without particles, > 0  | 0.01
    \endtable
    No cloud at the start time, or an emptyWeight <= 0, stops with a
    FatalError naming it.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmCloudIO.H"
#include "cloud.H"

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Write the cell weights (emptyWeight + particles per cell) of a"
        " particle-weighted decomposition, for decomposePar's weightField"
    );
    argList::noParallel();
    argList::addOption("cloud", "name", "the MPM cloud (default mpmCloud)");
    argList::addOption
    (
        "name", "field", "the weight field to write (default particleWeight)"
    );
    argList::addOption
    (
        "emptyWeight", "w", "weight of a cell without particles (default 0.01)"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    word cloudName("mpmCloud");
    {
        IOobject io
        (
            "mpmProperties", runTime.constant(), mesh,
            IOobject::READ_IF_PRESENT, IOobject::NO_WRITE
        );
        if (io.typeHeaderOk<IOdictionary>(true))
        {
            IOdictionary props(io);
            cloudName = props.getOrDefault<word>("cloudName", cloudName);
        }
    }
    args.readIfPresent("cloud", cloudName);
    const word fieldName(args.getOrDefault<word>("name", "particleWeight"));
    const scalar emptyWeight(args.getOrDefault<scalar>("emptyWeight", 0.01));
    if (!(emptyWeight > 0) || emptyWeight > 1e6)
    {
        FatalErrorInFunction
            << "Option -emptyWeight " << emptyWeight << ": the weight of an"
            << " empty cell must be in (0, 1e6]" << exit(FatalError);
    }

    mpmParticles P;
    if (!mpmCloudIO::read(mesh, cloudName, P))
    {
        FatalErrorInFunction
            << "No MPM cloud " << runTime.timePath()/cloud::prefix/cloudName
            << ": seed one with mpmSetParticles first" << exit(FatalError);
    }

    volScalarField weight
    (
        IOobject
        (
            fieldName, runTime.timeName(), mesh,
            IOobject::NO_READ, IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("emptyWeight", dimless, emptyWeight),
        calculatedFvPatchScalarField::typeName
    );
    forAll(P.cell, p)
    {
        weight.primitiveFieldRef()[P.cell[p]] += 1;
    }
    label filled = 0;
    forAll(weight, celli)
    {
        if (weight[celli] > emptyWeight) ++filled;
    }
    weight.write();

    Info<< "Particles: " << P.size() << " in " << filled << " of "
        << mesh.nCells() << " cells (" << 100.0*filled/max(mesh.nCells(), 1)
        << " %)" << nl
        << "Wrote " << runTime.timeName()/fieldName << ": " << emptyWeight
        << " + particles per cell" << nl << nl << "End" << nl << endl;

    return 0;
}

// ************************************************************************* //
