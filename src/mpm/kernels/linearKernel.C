/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "linearKernel.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
    defineTypeNameAndDebug(linearKernel, 0);
    addToRunTimeSelectionTable(mpmKernel, linearKernel, dictionary);
}


Foam::linearKernel::linearKernel
(
    const dictionary& dict,
    const mpmMeshView& mesh
)
:
    mpmKernel(dict, mesh)
{}


void Foam::linearKernel::compute
(
    const UList<vector>& x,
    const labelUList& cells,
    kernelWeights& out
) const
{
    out.clear();
    const labelList& cv = mesh_.cellVertices();
    mpmMeshView::shapeValues sv;
    forAll(x, p)
    {
        const label c = cells[p];
        mesh_.shapeFunctions(c, x[p], sv);
        const label b = mesh_.cellBegin(c);
        for (label i = 0; i < sv.n; ++i)
        {
            out.append(cv[b + i], sv.B[i], sv.gradB[i]);
        }
        out.endParticle();
    }
}


// ************************************************************************* //
