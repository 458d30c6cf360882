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

bsmsData::world Foam::bsmsExportWorld
(
    const bsmsPooling& levels,
    const pointField& x
)
{
    if (levels.nLevels() == 0 || x.size() != levels.graph(0).nNodes())
    {
        FatalErrorInFunction
            << x.size() << " world positions for "
            << (levels.nLevels() ? levels.graph(0).nNodes() : label(0))
            << " finest nodes" << exit(FatalError);
    }
    bsmsData::world w;
    for (label l = 0; l < levels.nLevels(); ++l)
    {
        const meshGraph& c = levels.contact(l);
        bsmsData::worldLevel out;
        const labelList finest(levels.finestNodes(l));
        out.positions.reserve(3*finest.size());
        for (const label i : finest)
        {
            out.positions.push_back(x[i].x());
            out.positions.push_back(x[i].y());
            out.positions.push_back(x[i].z());
        }
        out.offsets.assign(c.offsets().begin(), c.offsets().end());
        out.neighbours.assign(c.neighbours().begin(), c.neighbours().end());
        w.levels.push_back(std::move(out));
    }
    return w;
}


// ************************************************************************* //
