/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Application
    bsmsLevels

Group
    mpmFoam utilities

Description
    Builds the multi-level graphs of BSMS-GNN (dissertation 4.2.2:
    bi-stride pooling, adjacency enhancement (4.1), contact edges) of the
    case's mesh and writes each level as legacy VTK polydata for ParaView
    (the pictures of Fig. 4.4):
        VTK/bsmsLevels/level<l>.vtk
    nodes as vertices and edges as lines, with the cell field edgeType
    (0 node, 1 mesh edge, 2 contact edge) and the point fields finestNode
    (the node's index on level 0: cell or point label) and weight (the
    transition weight w of 4.3.2, one on level 0).

    The log has one line per level: nodes, edges, contact edges, connected
    components (the same on every level), nodes relative to the previous
    level, wall-clock seconds to build the level (level 0: the graph from
    the mesh), and the total.  With -check it also verifies, per level,
    that every node not pooled has a pooled neighbour (2-CC), that every
    contact edge has an image on the next level (4.2.2), that the level
    has the finest graph's number of components, and that down- then
    up-sampling a constant returns it to 1e-12 (4.3.2; round-off is about
    1e-14), and exits with status 1 if any check fails.

Usage
    bsmsLevels [-case dir] [-dict file] [-check] [-noWrite]

    system/bsmsDict:
    \verbatim
        graph       cells;          // cells | points
        seeding     closeCenter;    // closeCenter | minAve
        minNodes    100;
        contactRadius 0.001;        // optional
    \endverbatim
    \table
        Property  | Description                                  | Required | Default
        graph     | nodes: cells (centres, edges = internal faces), points (edges = mesh edges) or lagrangian (a recorded cloud) | yes |
        seeding   | closeCenter (Algorithm 2) or minAve (Algorithm 3) | yes |
        minNodes  | stop at the first level with fewer nodes     | no  | 100
        maxLevels | most levels, the finest included             | no  | 32
        balance   | see bsmsPooling.H, in [0, 0.5]               | no  | 0.45
        contactRadius | contact edges between nodes of different bodies closer than this [m] | no | none
    \endtable
    Bad or missing entries stop with a FatalIOError naming the file and the
    entry.  Serial only.

    Moving solids (graph lagrangian): the nodes are the material points of
    a recorded MPM case and its actuators' nodes (lagrangianRecording: the
    entries cloud, meshRadius, worldRadius, actuatorSpacing), the mesh
    edges join nodes of a body within meshRadius in the first written
    frame, and the contact edges are the world edges at the frame shown
    (entry time, default the latest written): nodes of different bodies
    within worldRadius.  The levels pool the reference graph; the VTK
    shows every level at the world positions of the frame, with the point
    field kind (0 free, 1 actuator, 2 fixed).
    \verbatim
        graph           lagrangian;
        seeding         closeCenter;
        meshRadius      0.015;
        worldRadius     0.012;
        actuatorSpacing 0.01;
        time            0.3;            // optional: the frame shown
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "polyMesh.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "dictionaryChecks.H"
#include "meshGraph.H"
#include "contactEdges.H"
#include "lagrangianRecording.H"
#include "bsmsPooling.H"
#include "bsmsTransition.H"

#include <chrono>
#include <cstdio>

using namespace Foam;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Level l of the pooling as legacy VTK polydata
void writeLevel
(
    const fileName& file,
    const bsmsPooling& P,
    const label l,
    const scalarUList& weights,
    const pointField& shown,
    const labelUList& kind
)
{
    const meshGraph& g = P.graph(l);
    const meshGraph& c = P.contact(l);
    const label n = g.nNodes();
    const label nE = g.nEdges(), nC = c.nEdges();
    const labelList finest(P.finestNodes(l));

    OFstream os(file);
    os.precision(12);
    os  << "# vtk DataFile Version 3.0" << nl
        << "bsmsLevels level " << l << ": " << n << " nodes, " << nE
        << " edges, " << nC << " contact edges" << nl
        << "ASCII" << nl
        << "DATASET POLYDATA" << nl
        << "POINTS " << n << " double" << nl;
    for (const label i : finest)
    {
        const point& p = shown[i];
        os  << p.x() << ' ' << p.y() << ' ' << p.z() << nl;
    }
    os  << "VERTICES " << n << ' ' << 2*n << nl;
    for (label i = 0; i < n; ++i) os << "1 " << i << nl;
    os  << "LINES " << nE + nC << ' ' << 3*(nE + nC) << nl;
    for (const meshGraph* h : {&g, &c})
    {
        for (label i = 0; i < n; ++i)
        {
            for (label k = h->offsets()[i]; k < h->offsets()[i + 1]; ++k)
            {
                const label j = h->neighbours()[k];
                if (j > i) os << "2 " << i << ' ' << j << nl;
            }
        }
    }
    os  << "CELL_DATA " << n + nE + nC << nl
        << "SCALARS edgeType int 1" << nl
        << "LOOKUP_TABLE default" << nl;
    for (label i = 0; i < n; ++i) os << "0" << nl;
    for (label e = 0; e < nE; ++e) os << "1" << nl;
    for (label e = 0; e < nC; ++e) os << "2" << nl;
    os  << "POINT_DATA " << n << nl
        << "SCALARS finestNode int 1" << nl
        << "LOOKUP_TABLE default" << nl;
    for (const label i : finest) os << i << nl;
    os  << "SCALARS weight double 1" << nl
        << "LOOKUP_TABLE default" << nl;
    for (const scalar w : weights) os << w << nl;
    if (kind.size())
    {
        os  << "SCALARS kind int 1" << nl
            << "LOOKUP_TABLE default" << nl;
        for (const label i : finest) os << kind[i] << nl;
    }
}


//- Nodes of g neither pooled nor next to a pooled node (2-CC: none)
label uncovered(const meshGraph& g, const labelUList& pooled)
{
    std::vector<char> in(g.nNodes(), 0);
    for (const label p : pooled) in[p] = 1;
    label bad = 0;
    for (label i = 0; i < g.nNodes(); ++i)
    {
        bool ok = in[i];
        for (label k = g.offsets()[i]; !ok && k < g.offsets()[i + 1]; ++k)
        {
            ok = in[g.neighbours()[k]];
        }
        bad += !ok;
    }
    return bad;
}


//- Contact edges (i, j) of level l with no contact edge (i', j') on level
//  l + 1 between pooled i' in {i} + N(i) and j' in {j} + N(j)
label lostContacts(const bsmsPooling& P, const label l)
{
    const meshGraph& g = P.graph(l);
    const meshGraph& c = P.contact(l);
    const meshGraph& cc = P.contact(l + 1);
    labelList coarseOf(g.nNodes(), -1);
    forAll(P.pooled(l), k) coarseOf[P.pooled(l)[k]] = k;
    DynamicList<label> ci, cj;
    auto images = [&](const label i, DynamicList<label>& out)
    {
        out.clear();
        if (coarseOf[i] >= 0) out.append(coarseOf[i]);
        for (label k = g.offsets()[i]; k < g.offsets()[i + 1]; ++k)
        {
            const label m = coarseOf[g.neighbours()[k]];
            if (m >= 0) out.append(m);
        }
    };
    label lost = 0;
    for (label i = 0; i < g.nNodes(); ++i)
    {
        for (label k = c.offsets()[i]; k < c.offsets()[i + 1]; ++k)
        {
            const label j = c.neighbours()[k];
            if (j < i) continue;
            images(i, ci);
            images(j, cj);
            bool kept = false;
            for (const label a : ci)
                for (const label b : cj)
                    kept = kept || cc.adjacent(a, b);
            lost += !kept;
        }
    }
    return lost;
}


double secondsSince(const std::chrono::steady_clock::time_point& t0)
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Build the BSMS-GNN multi-level graphs of the mesh and write them"
        " as VTK; settings in system/bsmsDict"
    );
    argList::noParallel();
    #include "addDictOption.H"
    argList::addBoolOption
    (
        "check",
        "verify 2-CC, contact edges and transitions on every level"
    );
    argList::addBoolOption("noWrite", "do not write the VTK files");

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createPolyMesh.H"

    using namespace dictionaryChecks;

    const word dictName("bsmsDict");
    #include "setSystemMeshDictionaryIO.H"
    const IOdictionary dict(dictIO);

    if (!dict.found("graph", keyType::LITERAL))
    {
        missingEntry(dict, "graph", "one of 3(cells points lagrangian)");
    }
    const bool lagrangian =
        dict.get<word>("graph") == "lagrangian";
    bsmsPooling P(dict);

    // The finest graph, its contact (world) edges, the positions shown
    // and, for a Lagrangian graph, the node kinds
    const auto t0 = std::chrono::steady_clock::now();
    autoPtr<meshGraph> finePtr, contactPtr;
    pointField shown;
    labelList kinds;
    bool withContact = false;
    scalar radius = 0;
    if (lagrangian)
    {
        // The first written time (the material positions) and the one
        // shown (entry time, default the latest)
        instantList times(runTime.times());
        DynamicList<instant> written;
        for (const instant& t : times)
        {
            if (t.name() != "constant") written.append(t);
        }
        if (written.empty())
        {
            FatalIOErrorInFunction(dict)
                << "graph lagrangian: the case " << runTime.path()
                << " has no written time" << exit(FatalIOError);
        }
        instant shownTime(written.last());
        if (dict.found("time", keyType::LITERAL))
        {
            const scalar t = getAs<scalar>(dict, "time", "a written time");
            label k = -1;
            forAll(written, i)
            {
                if (mag(written[i].value() - t) < 1e-9*max(1, mag(t))) k = i;
            }
            if (k < 0)
            {
                OStringStream allowed;
                allowed << "a written time of the case, from "
                    << written.first().name() << " to "
                    << written.last().name();
                badEntry(dict, "time", Foam::name(t), allowed.str());
            }
            shownTime = written[k];
        }
        instantList frames(1, written.first());
        if (shownTime.name() != written.first().name())
        {
            frames.append(shownTime);
        }
        const lagrangianRecording rec(runTime, frames, dict);
        const lagrangianGraph g(rec.graph(rec.nFrames() - 1));
        finePtr.reset(new meshGraph(g.meshEdges()));
        contactPtr.reset(new meshGraph(g.worldEdges()));
        shown = g.x();
        kinds.setSize(g.nNodes());
        forAll(kinds, i) kinds[i] = label(g.kind()[i]);
        withContact = true;
        radius = rec.worldRadius();
        Info<< "Lagrangian graph of the cloud at t = " << shownTime.name()
            << " (material positions: t = " << written.first().name()
            << "): " << rec.nPoints() << " material points, "
            << rec.nNodes() - rec.nPoints() << " actuator nodes, "
            << g.nBodies() << " bodies; meshRadius " << rec.meshRadius()
            << ", worldRadius " << rec.worldRadius() << nl;
    }
    else
    {
        const meshGraph::nodeType type = getEnum
        (
            dict, "graph", meshGraph::nodeTypeNames, meshGraph::nodeType::cells
        );
        withContact = dict.found("contactRadius", keyType::LITERAL);
        radius = withContact ? getPositive(dict, "contactRadius") : scalar(0);
        finePtr.reset(new meshGraph(mesh, type));
        contactPtr.reset
        (
            new meshGraph
            (
                withContact
              ? contactEdges(finePtr(), radius)
              : meshGraph(finePtr->positions(), labelList(), labelList())
            )
        );
        shown = finePtr->positions();
    }
    const meshGraph& fine = finePtr();
    const meshGraph& contact = contactPtr();
    const double tGraph = secondsSince(t0);

    Info<< "BSMS levels of " << runTime.path() << nl
        << "    graph " << dict.get<word>("graph")
        << ", seeding " << P.seeding().type()
        << ", minNodes " << P.minNodes() << ", maxLevels " << P.maxLevels()
        << ", balance " << P.balance();
    if (withContact) Info<< ", contact radius " << radius;
    Info<< nl << endl;

    const auto t1 = std::chrono::steady_clock::now();
    P.build(fine, contact);
    const double tLevels = secondsSince(t1);

    const auto t2 = std::chrono::steady_clock::now();
    const PtrList<bsmsTransition> T(bsmsTransition::chain(P));
    const double tTransitions = secondsSince(t2);

    // The table
    Info<< "level      nodes       edges     contact  components   ratio"
        << "   time [s]" << nl;
    char buf[160];
    for (label l = 0; l < P.nLevels(); ++l)
    {
        const meshGraph& g = P.graph(l);
        const double t = l == 0 ? tGraph : P.seconds(l);
        if (l == 0)
        {
            std::snprintf
            (
                buf, sizeof(buf), "%5d %10d %11d %11d %11d %7s %10.3f",
                int(l), int(g.nNodes()), int(g.nEdges()),
                int(P.contact(l).nEdges()), int(g.nComponents()), "-", t
            );
        }
        else
        {
            std::snprintf
            (
                buf, sizeof(buf), "%5d %10d %11d %11d %11d %7.4f %10.3f",
                int(l), int(g.nNodes()), int(g.nEdges()),
                int(P.contact(l).nEdges()), int(g.nComponents()),
                double(g.nNodes())/P.graph(l - 1).nNodes(), t
            );
        }
        Info<< buf << nl;
    }
    std::snprintf
    (
        buf, sizeof(buf),
        "graph from mesh %.3f s, levels %.3f s, transitions %.3f s",
        tGraph, tLevels, tTransitions
    );
    Info<< nl << buf << nl << endl;

    // Checks
    bool failed = false;
    if (args.found("check"))
    {
        const label c0 = P.graph(0).nComponents();
        for (label l = 0; l + 1 < P.nLevels(); ++l)
        {
            const label bad = uncovered(P.graph(l), P.pooled(l));
            const label lost = withContact ? lostContacts(P, l) : 0;
            const scalarField one(T[l].nFine(), 1.0);
            const scalarField mid(T[l].downsample(one));
            const scalar err = max(mag(T[l].upsample(mid) - 1.0));
            const label comps = P.graph(l + 1).nComponents();
            const bool ok =
                bad == 0 && lost == 0 && err < 1e-12 && comps == c0;
            failed = failed || !ok;
            Info<< "check level " << l << " -> " << l + 1 << ": "
                << bad << " nodes without a pooled neighbour, "
                << lost << " contact edges lost, components " << comps
                << " (finest " << c0 << "), constant round trip error "
                << err << (ok ? "  OK" : "  FAILED") << nl;
        }
        Info<< "check: " << (failed ? "FAILED" : "OK") << nl << endl;
    }

    // VTK
    if (!args.found("noWrite"))
    {
        const fileName dir(runTime.path()/"VTK"/"bsmsLevels");
        if (isDir(dir)) rmDir(dir);
        mkDir(dir);
        scalarField w(P.graph(0).nNodes(), 1.0);
        for (label l = 0; l < P.nLevels(); ++l)
        {
            if (l > 0) w = T[l - 1].coarseWeights();
            const fileName file(dir/("level" + Foam::name(l) + ".vtk"));
            writeLevel(file, P, l, w, shown, kinds);
            Info<< "Wrote " << file << nl;
        }
    }

    Info<< nl << "End" << nl << endl;
    return failed ? 1 : 0;
}


// ************************************************************************* //
