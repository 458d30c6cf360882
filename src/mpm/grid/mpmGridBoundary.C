/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmGridBoundary.H"
#include "mpmMeshView.H"
#include "polyMesh.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "processorPolyPatch.H"
#include "dictionaryChecks.H"
#include "SubField.H"
#include "Map.H"
#include "Pair.H"
#include "mpmParallel.H"

const Foam::Enum<Foam::mpmGridBoundary::bcType>
Foam::mpmGridBoundary::bcTypeNames
({
    { bcType::free, "free" },
    { bcType::fixed, "fixed" },
    { bcType::slip, "slip" },
    { bcType::separable, "separable" },
    { bcType::outlet, "outlet" },
});


bool Foam::mpmGridBoundary::throughOutlet(const vector& x) const
{
    scalar best = GREAT;
    bool outlet = false;
    forAll(exitFaceCentre_, f)
    {
        const scalar d = magSqr(solved_ & (x - exitFaceCentre_[f]));
        if (d < best)
        {
            best = d;
            outlet = exitFaceOutlet_[f];
        }
    }
    return outlet;
}


void Foam::mpmGridBoundary::set
(
    const label v,
    const List<vector>& slipNormals,
    const bool fixed,
    const bool separable
)
{
    tensor P(I);
    vector sepN(Zero);
    if (fixed)
    {
        P = tensor::zero;
    }
    else
    {
        // Gram-Schmidt: remove each independent normal direction once
        FixedList<vector, 3> basis;
        label nb = 0;
        for (const vector& n0 : slipNormals)
        {
            vector n = n0;
            for (label j = 0; j < nb; ++j) n -= (n & basis[j])*basis[j];
            const scalar len = mag(n);
            if (nb < 3 && len > 1e-6*max(mag(n0), VSMALL))
            {
                basis[nb++] = n/len;
            }
        }
        if (separable && nb == 1)
        {
            sepN = basis[0];
        }
        else
        {
            for (label j = 0; j < nb; ++j) P -= basis[j]*basis[j];
        }
    }
    vertices_.append(v);
    projection_.append(P);
    separableNormal_.append(sepN);
}


Foam::mpmGridBoundary::mpmGridBoundary
(
    const polyMesh& mesh,
    const mpmMeshView& view,
    const dictionary& dict,
    const mpmParallel* par
)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    const labelList& pointVertex = view.pointVertex();

    const label nV = view.nVertices();
    List<DynamicList<vector>> normals(nV);
    List<bool> fixed(nV, false);
    List<bool> touched(nV, false);
    // Every normal of the vertex from a separable condition
    List<bool> separable(nV, true);

    // Every key must match a patch, unless it is a box region
    for (const entry& e : dict)
    {
        if (e.isDict() && e.dict().found("box", keyType::LITERAL))
        {
            const dictionary& bd = e.dict();
            const bcType t = dictionaryChecks::getEnum
            (
                bd, "type", bcTypeNames, bcType::free
            );
            const Pair<vector> box = dictionaryChecks::getAs<Pair<vector>>
            (
                bd, "box", "two points ((xmin ymin zmin) (xmax ymax zmax))"
            );
            if (t == bcType::outlet)
            {
                dictionaryChecks::badEntry(bd, "type", "outlet",
                    "fixed, slip, separable or free (an outlet is a patch,"
                    " not a box)");
            }
            vector n(Zero);
            if (t == bcType::slip || t == bcType::separable)
            {
                n = dictionaryChecks::getAs<vector>(bd, "normal", "a non-zero vector");
                if (mag(n) < VSMALL)
                {
                    dictionaryChecks::badEntry(bd, "normal", "(0 0 0)", "a non-zero vector");
                }
                n /= mag(n);
            }
            label count = 0;
            forAll(view.vertices(), v)
            {
                const vector& x = view.vertices()[v];
                bool in = true;
                for (label a = 0; a < view.dim(); ++a)
                {
                    const label k = view.axis(a);
                    in = in && x[k] >= box.first()[k] && x[k] <= box.second()[k];
                }
                if (!in || t == bcType::free) continue;
                touched[v] = true;
                ++count;
                if (t == bcType::fixed) fixed[v] = true;
                else normals[v].append(n);
                if (t != bcType::separable) separable[v] = false;
            }
            Info<< "MPM grid condition " << e.keyword() << ": "
                << bcTypeNames[t] << " on " << count << " vertices in the box"
                << endl;
            continue;
        }

        bool matched = false;
        for (const polyPatch& pp : patches)
        {
            if (e.keyword().match(pp.name())) { matched = true; break; }
        }
        if (!matched)
        {
            OStringStream allowed;
            allowed << "patch names or patterns of " << patches.names();
            dictionaryChecks::badEntry(dict, e.keyword(),
                "(a patch name matching no patch)", allowed.str());
        }
        if (!e.isDict())
        {
            dictionaryChecks::badEntry(dict, e.keyword(),
                dictionaryChecks::entryText(dict, e.keyword()),
                "a sub-dictionary { type fixed | slip | separable | free"
                " | outlet; }");
        }
    }

    // Outlets: every face a particle can leave through, and whether it is
    // on an outlet (the nearest one tells a leaving particle's patch)
    bool anyOutlet = false;
    for (const polyPatch& pp : patches)
    {
        const dictionary* pd = dict.findDict(pp.name(), keyType::REGEX);
        if
        (
            pd && !pd->found("box", keyType::LITERAL)
         && dictionaryChecks::getEnum(*pd, "type", bcTypeNames, bcType::free)
         == bcType::outlet
        )
        {
            anyOutlet = true;
        }
    }
    if (anyOutlet)
    {
        solved_ = tensor::I - view.offAxes();
        for (const polyPatch& pp : patches)
        {
            if
            (
                isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp)
             || isA<processorPolyPatch>(pp)
            )
            {
                continue;
            }
            const dictionary* pd = dict.findDict(pp.name(), keyType::REGEX);
            const bool outlet =
                pd && !pd->found("box", keyType::LITERAL)
             && dictionaryChecks::getEnum(*pd, "type", bcTypeNames, bcType::free)
             == bcType::outlet;
            for (const vector& c : pp.faceCentres())
            {
                exitFaceCentre_.append(c);
                exitFaceOutlet_.append(outlet);
            }
        }
    }

    for (const polyPatch& pp : patches)
    {
        if
        (
            isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp)
         || isA<processorPolyPatch>(pp)
        )
        {
            continue;
        }
        const dictionary* pd = dict.findDict(pp.name(), keyType::REGEX);
        if (!pd || pd->found("box", keyType::LITERAL)) continue;
        const bcType t = dictionaryChecks::getEnum
        (
            *pd, "type", bcTypeNames, bcType::free
        );
        if (t == bcType::free || t == bcType::outlet) continue;

        // Per vertex: the area-weighted normal of this patch
        Map<vector> patchNormal;
        forAll(pp, i)
        {
            const face& f = pp[i];
            const vector a = pp.faceAreas()[i];
            for (const label p : f)
            {
                const label v = pointVertex[p];
                if (v < 0) continue;
                touched[v] = true;
                if (t != bcType::separable) separable[v] = false;
                if (t == bcType::fixed) fixed[v] = true;
                else
                {
                    // (Map's operator() would start from an uninitialised vector)
                    auto iter = patchNormal.find(v);
                    if (iter.found()) iter.val() += a;
                    else patchNormal.insert(v, a);
                }
            }
        }
        if (par)
        {
            // The copies of a vertex sum the normals of every rank's faces
            // (zero where a rank has none); a vertex touched anywhere is
            // touched on every copy
            List<vector> an(nV, Zero);
            scalarList hit(nV, Zero);
            forAllConstIters(patchNormal, iter)
            {
                an[iter.key()] = iter.val();
                hit[iter.key()] = 1;
            }
            if (t == bcType::fixed)
            {
                forAll(fixed, v) hit[v] = fixed[v] ? 1 : 0;
            }
            par->sumShared(an);
            par->sumShared(hit);
            forAll(hit, v)
            {
                if (hit[v] <= 0) continue;
                touched[v] = true;
                if (t != bcType::separable) separable[v] = false;
                if (t == bcType::fixed) fixed[v] = true;
                else normals[v].append(an[v]/max(mag(an[v]), VSMALL));
            }
            continue;
        }
        forAllConstIters(patchNormal, iter)
        {
            normals[iter.key()].append(iter.val()/max(mag(iter.val()), VSMALL));
        }
    }

    forAll(touched, v)
    {
        if (touched[v])
        {
            set(v, normals[v], fixed[v], separable[v]);
        }
    }
}


// ************************************************************************* //
