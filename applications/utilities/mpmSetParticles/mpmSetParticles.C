/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
Application
    mpmSetParticles

Group
    mpmFoam utilities

Description
    Seeds the material points of an MPM case from system/mpmSetParticlesDict
    and writes them as the lagrangian cloud of the start time (replacing
    any cloud there).  Regions are filled on a lattice of the given spacing
    (particle volume spacing^dim: per unit depth in 2D, per unit area in
    1D) or with perCell^dim particles per cell (perCell^2 on triangles; not
    for tetrahedra), each with a material of constant/mpmProperties, a
    velocity (uniform, plus an optional sine profile) and an initial
    deformation gradient F.  The region is the body as it is now, deformed
    by F: a particle's current volume is spacing^dim (or its share of the
    cell), its reference volume V0 that over det F, and its mass rho V0
    with rho the material's (reference) density: a body compressed to
    F = 0.75 I fills its region at 1/det F = 2.37 times rho.

Usage
    system/mpmSetParticlesDict:
    \verbatim
        regions
        (
            bar
            {
                type        box;            // box | sphere | cylinder | star | cellZone
                min         (0 0 0);        // box
                max         (25 1 1);
                // centre (0 0 0); radius 0.2;            sphere, cylinder
                // axis (0 0 1);                          cylinder
                // centre, radius (the tips), coreRadius 0.1;
                // baseRadius 0.08; spikes ((1 0 0) ...); star
                // zone  solid;                           cellZone
                material    steel;
                spacing     0.5;            // or: perCell 2;
                velocity    (0 0 0);        // optional, default 0
                velocitySine                // optional: + A sin(k . x)
                {
                    amplitude   (0.75 0 0);
                    wavenumber  (0.0628319 0 0);
                }
                F           (1 0 0 0 1 0 0 0 1);   // optional, default I
                densityVariation            // optional: masses rho V0
                {                           // (1 + a xi), xi uniform in
                    amplitude   0.05;       // [-1, 1], hashed from seed
                    seed        1;          // and position (see
                }                           // densityVariation.H)
            }
        );
    \endverbatim
    A region whose particles would lie outside the mesh, a box whose max
    is not above its min, an unknown material or type, a spacing <= 0 or
    perCell < 1, a velocity with a component beyond 1e30 m/s, an F with a
    component beyond 1e3 or det F outside [1e-6, 1e6], and regions that
    seed no particle at all stop with a FatalIOError naming the entry.

    A star is a ball of radius coreRadius with a cone (a spike) along each
    direction of spikes: its apex at distance radius from the centre, its
    base a disc of radius baseRadius through the centre, normal to the
    direction (coreRadius and baseRadius in (0, radius]).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "mpmMeshView.H"
#include "mpmSolver.H"
#include "mpmCloudIO.H"
#include "densityVariation.H"
#include "dictionaryChecks.H"
#include "cellZoneMesh.H"
#include "cloud.H"

using namespace Foam;

namespace
{

enum class regionType { box, sphere, cylinder, star, cellZone };
const Enum<regionType> regionTypeNames
({
    { regionType::box, "box" },
    { regionType::sphere, "sphere" },
    { regionType::cylinder, "cylinder" },
    { regionType::star, "star" },
    { regionType::cellZone, "cellZone" },
});

struct region
{
    regionType type;
    vector lo, hi, centre, axis;
    scalar radius;
    scalar coreRadius, baseRadius;
    List<vector> spikes;
    labelHashSet zoneCells;

    bool inside(const vector& x, const label celli) const
    {
        switch (type)
        {
            case regionType::box:
                return x.x() >= lo.x() && x.y() >= lo.y() && x.z() >= lo.z()
                    && x.x() <= hi.x() && x.y() <= hi.y() && x.z() <= hi.z();
            case regionType::sphere:
                return magSqr(x - centre) <= radius*radius;
            case regionType::cylinder:
            {
                const vector d = x - centre;
                return magSqr(d - (d & axis)*axis) <= radius*radius;
            }
            case regionType::star:
            {
                // The core ball, or a spike's cone: axial s in [0, radius],
                // off the axis at most baseRadius (1 - s/radius)
                const vector d = x - centre;
                if (magSqr(d) <= coreRadius*coreRadius) return true;
                for (const vector& e : spikes)
                {
                    const scalar s = d & e;
                    if (s < 0 || s > radius) continue;
                    const scalar rho = baseRadius*(1 - s/radius);
                    if (magSqr(d - s*e) <= rho*rho) return true;
                }
                return false;
            }
            case regionType::cellZone:
                return zoneCells.found(celli);
        }
        return false;
    }

    //- The entries that place the region, for messages
    string placement() const
    {
        OStringStream os;
        switch (type)
        {
            case regionType::box:
                os << "min " << lo << ", max " << hi;
                break;
            case regionType::cellZone:
                os << "zone of " << zoneCells.size() << " cells";
                break;
            default:
                os << "centre " << centre << ", radius " << radius;
        }
        return os.str();
    }
};

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Seed MPM particles from system/mpmSetParticlesDict into the"
        " lagrangian cloud of the start time"
    );
    argList::noParallel();

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    using namespace dictionaryChecks;

    IOdictionary mpmProperties
    (
        IOobject("mpmProperties", runTime.constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    IOdictionary setDict
    (
        IOobject("mpmSetParticlesDict", runTime.system(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE)
    );
    const word cloudName
    (
        mpmProperties.getOrDefault<word>("cloudName", "mpmCloud")
    );

    const mpmMeshView view(mesh);
    mpmSolver solver(view, mpmProperties, mpmGridBoundary());
    const label dim = view.dim();

    // Mid-plane of the directions that are not solved (2D, 1D)
    const tensor Q = view.offAxes();
    const vector mid = Q & mesh.bounds().centre();
    // Cell measure in the solved dimensions
    scalar depth = 1;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (Q(d, d) > 0) depth *= mesh.bounds().span()[d];
    }

    mpmParticles P;
    // Each region's placement, for the message if all of them are empty
    OStringStream placements;
    const entry* re = setDict.findEntry("regions", keyType::LITERAL);
    if (!re || !re->isStream())
    {
        missingEntry(setDict, "regions", "a list of region dictionaries ( name { type box; ... } ... )");
    }
    const PtrList<entry> regions(re->stream());

    for (const entry& e : regions)
    {
        if (!e.isDict())
        {
            badEntry(setDict, "regions", e.keyword(), "name { type ...; } entries");
        }
        // Name the region's dictionary after the file, for messages
        dictionary d(e.dict());
        d.name() = setDict.objectPath() + ".regions." + e.keyword();
        region r;
        r.type = getEnum(d, "type", regionTypeNames, regionType::box);
        switch (r.type)
        {
            case regionType::box:
                for (const word k : {"min", "max"})
                {
                    if (!d.found(k, keyType::LITERAL))
                    {
                        missingEntry
                        (
                            d, k,
                            d.found("type", keyType::LITERAL)
                          ? "a point (x y z)"
                          : "a point (x y z): a region without an entry"
                            " 'type' is a box"
                        );
                    }
                }
                r.lo = getBoundedVector(d, "min", Zero, 1e30, "a point");
                r.hi = getBoundedVector(d, "max", Zero, 1e30, "a point");
                for (label a = 0; a < dim; ++a)
                {
                    const label k = view.axis(a);
                    if (!(r.hi[k] > r.lo[k]))
                    {
                        OStringStream found;
                        found << r.hi << " (min " << r.lo << ")";
                        badEntry(d, "max", found.str(),
                            "a point above min in each solved direction");
                    }
                }
                break;
            case regionType::sphere:
            case regionType::cylinder:
            case regionType::star:
                if (!d.found("centre", keyType::LITERAL))
                {
                    missingEntry(d, "centre", "a point (x y z)");
                }
                r.centre = getBoundedVector(d, "centre", Zero, 1e30, "a point");
                r.radius = getInRange(d, "radius", 1, 0, 1e30);
                if (r.type == regionType::cylinder)
                {
                    if (!d.found("axis", keyType::LITERAL))
                    {
                        missingEntry(d, "axis", "a direction (x y z)");
                    }
                    r.axis = getBoundedVector(d, "axis", Zero, 1e30, "a direction");
                    if (mag(r.axis) < VSMALL)
                    {
                        badEntry(d, "axis", "(0 0 0)", "a non-zero direction");
                    }
                    r.axis /= mag(r.axis);
                }
                if (r.type == regionType::star)
                {
                    r.coreRadius = getInRange(d, "coreRadius", 0, r.radius);
                    r.baseRadius = getInRange(d, "baseRadius", 0, r.radius);
                    const string allowedSpikes
                    (
                        "a non-empty list of non-zero directions ((x y z) ...)"
                    );
                    r.spikes = getAs<List<vector>>(d, "spikes", allowedSpikes);
                    if (r.spikes.empty())
                    {
                        badEntry(d, "spikes", "()", allowedSpikes);
                    }
                    for (vector& e : r.spikes)
                    {
                        if (!(mag(e) > VSMALL) || !(mag(e) < 1e30))
                        {
                            badEntry(d, "spikes", Foam::name(e), allowedSpikes);
                        }
                        e /= mag(e);
                    }
                }
                break;
            case regionType::cellZone:
            {
                const word zone(getAs<word>(d, "zone", "the name of a cellZone"));
                const label zi = mesh.cellZones().findZoneID(zone);
                if (zi < 0)
                {
                    OStringStream allowed;
                    allowed << "one of the cellZones " << mesh.cellZones().names();
                    badEntry(d, "zone", zone, allowed.str());
                }
                r.zoneCells.insert(mesh.cellZones()[zi]);
                break;
            }
        }

        // A region reaching outside the mesh (in the solved directions)
        // would seed particles there: an error, for every seeding mode
        if (r.type != regionType::cellZone)
        {
            const vector lo =
                r.type == regionType::box ? r.lo : r.centre - vector::uniform(r.radius);
            const vector hi =
                r.type == regionType::box ? r.hi : r.centre + vector::uniform(r.radius);
            const word key(r.type == regionType::box ? "min" : "radius");
            for (label a = 0; a < dim; ++a)
            {
                const label k = view.axis(a);
                const scalar tol = 1e-9*mag(mesh.bounds().span());
                if
                (
                    lo[k] < mesh.bounds().min()[k] - tol
                 || hi[k] > mesh.bounds().max()[k] + tol
                )
                {
                    OStringStream found, allowed;
                    found << "a region from " << lo << " to " << hi
                        << " (" << r.placement()
                        << ": reaching outside the mesh)";
                    allowed << "regions inside the mesh bounds "
                        << mesh.bounds();
                    badEntry(d, key, found.str(), allowed.str());
                }
            }
        }

        const label mat = solver.materialIndex
        (
            getAs<word>(d, "material", "a material of constant/mpmProperties"), d
        );
        const scalar rho = solver.materials()[mat].rho();
        // (seeded heterogeneity: each particle's mass rho V0 (1 + a xi))
        const densityVariation variation(d);
        // Bounds that keep the solver's products (m |v|^2, stresses,
        // energies) finite
        const vector U0 = getBoundedVector(d, "velocity", Zero, 1e30, "a velocity");
        const string allowedF
        (
            "a deformation gradient (xx xy xz yx yy yz zx zy zz) with finite"
            " components of magnitude <= 1e3 and 1e-6 <= det F <= 1e6"
        );
        const tensor F0 = getAsOrDefault<tensor>(d, "F", tensor(I), allowedF);
        for (direction c = 0; c < tensor::nComponents; ++c)
        {
            if (!(mag(F0[c]) <= 1e3))
            {
                badEntry(d, "F", Foam::name(F0), allowedF);
            }
        }
        if (!(det(F0) >= 1e-6 && det(F0) <= 1e6))
        {
            badEntry(d, "F", Foam::name(F0) + " (det F = "
                + Foam::name(det(F0)) + ")", allowedF);
        }
        // The region is the body as it is now, deformed by F0: each
        // particle's current volume is its share of the region, its
        // reference volume that over det F0, its mass rho (the reference
        // density) times the reference volume
        const scalar J0 = det(F0);
        vector sineA(Zero), sineK(Zero);
        if (const dictionary* sd = d.findDict("velocitySine", keyType::LITERAL))
        {
            for (const word k : {"amplitude", "wavenumber"})
            {
                if (!sd->found(k, keyType::LITERAL))
                {
                    missingEntry(*sd, k, "a vector (x y z)");
                }
            }
            sineA = getBoundedVector(*sd, "amplitude", Zero, 1e30, "a velocity");
            sineK = getBoundedVector(*sd, "wavenumber", Zero, 1e30, "a wavenumber [1/m]");
        }
        auto velocity = [&](const vector& x)
        {
            return view.inPlane(U0 + sineA*std::sin(sineK & x));
        };

        const bool hasSpacing = d.found("spacing", keyType::LITERAL);
        const bool hasPerCell = d.found("perCell", keyType::LITERAL);
        if (hasSpacing == hasPerCell)
        {
            missingEntry(d, "spacing",
                "exactly one of 'spacing' (> 0) and 'perCell' (integer >= 1)");
        }

        const label before = P.size();
        label outside = 0;
        vector firstOutside(Zero);

        if (hasSpacing)
        {
            const scalar s = getPositive(d, "spacing", 1);
            // More lattice points than a label holds, or than memory
            // would take: stop before looping over them
            {
                scalar nTotal = 1;
                const boundBox& mb = mesh.bounds();
                for (label a = 0; a < dim; ++a)
                {
                    const label k = view.axis(a);
                    nTotal *= min(mb.span()[k]/s, scalar(1e10)) + 1;
                }
                if (nTotal > 1e9)
                {
                    badEntry(d, "spacing", Foam::name(s),
                        "a spacing that gives at most 1e9 lattice points"
                        " over the mesh bounds");
                }
            }
            // Lattice over the region's bounds, clipped to the mesh bounds
            boundBox bb(mesh.bounds());
            if (r.type == regionType::box)
            {
                bb = boundBox(max(r.lo, bb.min()), min(r.hi, bb.max()));
            }
            else if (r.type != regionType::cellZone)
            {
                bb = boundBox(r.centre - vector::uniform(r.radius), r.centre + vector::uniform(r.radius));
            }
            label n[3] = {1, 1, 1};
            for (label a = 0; a < dim; ++a)
            {
                const label k = view.axis(a);
                n[a] = max(label(0), label(std::floor((bb.max()[k] - bb.min()[k])/s + 1e-9)));
            }
            label guess = 0;
            for (label i = 0; i < n[0]; ++i)
            for (label j = 0; j < (dim > 1 ? n[1] : 1); ++j)
            for (label l = 0; l < (dim > 2 ? n[2] : 1); ++l)
            {
                vector x(mid);
                const label idx[3] = {i, j, l};
                for (label a = 0; a < dim; ++a)
                {
                    const label k = view.axis(a);
                    x[k] = bb.min()[k] + (idx[a] + 0.5)*s;
                }
                const label c = view.findCell(x, guess);
                if (!r.inside(x, c)) continue;
                if (c < 0)
                {
                    if (!outside) firstOutside = x;
                    ++outside;
                    continue;
                }
                guess = c;
                const scalar V0 = std::pow(s, dim)/J0;
                P.append
                (
                    x, velocity(x), F0, rho*V0*variation.factor(x), V0,
                    mat, c
                );
            }
        }
        else
        {
            const label N = getLabelAtLeast(d, "perCell", 1, 1);
            if (std::pow(scalar(N), dim)*view.nCells() > 1e9)
            {
                badEntry(d, "perCell", Foam::name(N),
                    "an integer >= 1 that gives at most 1e9 particles"
                    " (perCell^dim times the number of cells)");
            }
            mpmMeshView::shapeValues sv;
            for (label c = 0; c < view.nCells(); ++c)
            {
                const vector cc = (I - Q) & mesh.cellCentres()[c];
                if (!r.inside(cc + mid, c)) continue;
                const mpmMeshView::shapeType st = view.shape(c);
                if (st == mpmMeshView::TET)
                {
                    badEntry(d, "perCell", Foam::name(N),
                        "'spacing' on tetrahedral meshes (perCell takes"
                        " segments, triangles, quads and hexes)");
                }
                const scalar Vc = mesh.cellVolumes()[c]/depth;
                DynamicList<vector> pts;
                const labelList& cv = view.cellVertices();
                const label b = view.cellBegin(c);
                auto vtx = [&](label i) { return view.vertices()[cv[b + i]]; };
                if (st == mpmMeshView::TRIANGLE)
                {
                    // Centroids of the N^2 sub-triangles
                    for (label i = 0; i < N; ++i)
                    for (label j = 0; i + j < N; ++j)
                    {
                        const scalar l1 = (i + 1.0/3)/N, l2 = (j + 1.0/3)/N;
                        pts.append(vtx(0) + l1*(vtx(1) - vtx(0)) + l2*(vtx(2) - vtx(0)));
                        if (i + j + 1 < N)
                        {
                            const scalar m1 = (i + 2.0/3)/N, m2 = (j + 2.0/3)/N;
                            pts.append(vtx(0) + m1*(vtx(1) - vtx(0)) + m2*(vtx(2) - vtx(0)));
                        }
                    }
                }
                else
                {
                    // Lattice in reference coordinates (segment/quad/hex)
                    const label nv = mpmMeshView::nShapeVertices(st);
                    for (label i = 0; i < N; ++i)
                    for (label j = 0; j < (dim > 1 ? N : 1); ++j)
                    for (label l = 0; l < (dim > 2 ? N : 1); ++l)
                    {
                        const scalar xi[3] = {(i + 0.5)/N, (j + 0.5)/N, (l + 0.5)/N};
                        vector x(Zero);
                        if (st == mpmMeshView::SEGMENT)
                        {
                            x = (1 - xi[0])*vtx(0) + xi[0]*vtx(1);
                        }
                        else
                        {
                            static const scalar ref[8][3] =
                            {
                                {0,0,0},{1,0,0},{1,1,0},{0,1,0},
                                {0,0,1},{1,0,1},{1,1,1},{0,1,1}
                            };
                            for (label v = 0; v < nv; ++v)
                            {
                                scalar w = 1;
                                for (label a = 0; a < dim; ++a)
                                {
                                    w *= ref[v][a] ? xi[a] : 1 - xi[a];
                                }
                                x += w*vtx(v);
                            }
                        }
                        pts.append(x);
                    }
                }
                for (vector x : pts)
                {
                    x = ((I - Q) & x) + mid;
                    const scalar V0 = Vc/pts.size()/J0;
                    P.append
                    (
                        x, velocity(x), F0, rho*V0*variation.factor(x), V0,
                        mat, c
                    );
                }
            }
        }

        if (outside)
        {
            OStringStream found, allowed;
            found << outside << " particles outside the mesh, the first at "
                << firstOutside;
            allowed << "regions inside the mesh, bounds " << mesh.bounds();
            badEntry(d, "type", found.str(), allowed.str());
        }
        // The fill goes in the line too: an empty region is often a
        // spacing larger than the region
        placements << nl << "        " << e.keyword() << ": "
            << r.placement() << ", "
            << (hasSpacing
                ? "spacing " + Foam::name(d.get<scalar>("spacing"))
                : "perCell " + Foam::name(d.get<label>("perCell"))).c_str();
        if (P.size() == before)
        {
            WarningInFunction
                << "Region " << e.keyword() << " holds no particle" << endl;
        }
        Info<< "Region " << e.keyword() << ": " << P.size() - before
            << " particles of material "
            << solver.materials()[mat].name();
        if (variation.amplitude() > 0)
        {
            Info<< ", density varied by +-" << variation.amplitude()
                << " (seeded)";
        }
        Info<< nl;
    }

    if (P.size() == 0)
    {
        FatalIOErrorInFunction(setDict)
            << "Entry 'regions' in " << setDict.name() << " seeds no"
            << " particle: every region is empty:"
            << placements.str().c_str() << nl
            << "    allowed: regions that hold at least one particle"
            << exit(FatalIOError);
    }

    solver.initialise(P);
    mpmCloudIO::write(mesh, cloudName, P);
    Info<< nl << "Wrote " << P.size() << " particles to "
        << runTime.timePath()/cloud::prefix/cloudName << nl << "End" << nl;

    return 0;
}

// ************************************************************************* //
