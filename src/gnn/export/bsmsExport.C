/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsExport.H"
#include "bsmsPooling.H"
#include "bsmsTransition.H"
#include "error.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

bsmsData::level Foam::bsmsExportLevel(const meshGraph& g)
{
    bsmsData::level out;
    out.nNodes = g.nNodes();
    out.positions.reserve(3*g.nNodes());
    for (const point& p : g.positions())
    {
        out.positions.push_back(p.x());
        out.positions.push_back(p.y());
        out.positions.push_back(p.z());
    }
    out.offsets.assign(g.offsets().begin(), g.offsets().end());
    out.neighbours.assign(g.neighbours().begin(), g.neighbours().end());
    return out;
}


bsmsData::hierarchy Foam::bsmsExport(const meshGraph& g, const int dim)
{
    bsmsData::hierarchy h;
    h.dim = dim;
    h.levels.push_back(bsmsExportLevel(g));
    const std::string bad = h.check();
    if (!bad.empty())
    {
        FatalErrorInFunction << "Inconsistent graph export: " << bad.c_str()
            << exit(FatalError);
    }
    return h;
}


bsmsData::hierarchy Foam::bsmsExport(const bsmsPooling& levels, const int dim)
{
    bsmsData::hierarchy h;
    h.dim = dim;
    for (label l = 0; l < levels.nLevels(); ++l)
    {
        h.levels.push_back(bsmsExportLevel(levels.graph(l)));
    }
    const PtrList<bsmsTransition> T = bsmsTransition::chain(levels);
    for (const bsmsTransition& t : T)
    {
        bsmsData::transition out;
        out.nFine = t.nFine();
        out.nCoarse = t.nCoarse();
        out.offsets.assign(t.offsets().begin(), t.offsets().end());
        out.senders.assign(t.senders().begin(), t.senders().end());
        out.C.assign(t.contributions().begin(), t.contributions().end());
        h.transitions.push_back(std::move(out));
    }
    const std::string bad = h.check();
    if (!bad.empty())
    {
        FatalErrorInFunction << "Inconsistent BSMS export: " << bad.c_str()
            << exit(FatalError);
    }
    return h;
}

// ************************************************************************* //
