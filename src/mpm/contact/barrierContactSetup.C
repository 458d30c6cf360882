/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
    barrierContact: the settings, the contact faces of the patches and
    zones (gathered over the ranks) and the per-cell candidate faces,
    built once; the geometry is in barrierContactGeometry.C
\*---------------------------------------------------------------------------*/

#include "barrierContact.H"
#include "dictionaryChecks.H"
#include "polyMesh.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "faceZoneMesh.H"
#include "Pstream.H"
#include "boundBox.H"
#include "SubField.H"
#include "ops.H"
#include <algorithm>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::barrierContact::readSettings
(
    const dictionary& dict,
    const scalar hMean
)
{
    using namespace dictionaryChecks;

    if (mesh_.dim() < 2)
    {
        FatalIOErrorInFunction(dict)
            << "Barrier contact (" << dict.name() << ") needs a 2D or 3D"
            << " mesh; this one is " << mesh_.dim() << "D"
            << exit(FatalIOError);
    }
    if (!(hMean > 0) && !dict.found("dHat", keyType::LITERAL))
    {
        const bool zones = !zoneNames_.empty();
        badEntry
        (
            dict, zones ? "zones" : "patches",
            entryText(dict, zones ? "zones" : "patches"),
            "patches or zones with faces (these have none, so dHat has no"
            " default)"
        );
    }
    dHat_ = getPositive(dict, "dHat", 0.25*hMean);
    stiffness_ = getPositive(dict, "stiffness", 1);
    friction_ = getAsOrDefault<scalar>
    (
        dict, "friction", 0, "a finite number >= 0"
    );
    if (!(friction_ >= 0) || !std::isfinite(friction_))
    {
        badEntry(dict, "friction", Foam::name(friction_), "a finite number >= 0");
    }
    epsV_ = getPositive(dict, "epsV", 1e-3);
}


void Foam::barrierContact::buildCellFaces()
{
    // Faces ordered by patch (stable), so a cell's list is too
    {
        labelList order(faces_.size());
        forAll(order, i) order[i] = i;
        std::stable_sort
        (
            order.begin(), order.end(),
            [this](const label i, const label j)
            {
                return faces_[i].patch < faces_[j].patch;
            }
        );
        List<face> sorted(faces_.size());
        forAll(order, i) sorted[i] = faces_[order[i]];
        faces_.transfer(sorted);
    }

    const label nCells = mesh_.nCells();
    const List<vector>& xv = mesh_.vertices();
    const labelList& cv = mesh_.cellVertices();

    // Each cell's centre and radius R; the search radius dHat + R covers
    // every point of the cell
    List<vector> centre(nCells);
    scalarList radius(nCells);
    scalar rMax = 0;
    for (label c = 0; c < nCells; ++c)
    {
        vector xc(Zero);
        const label n = mesh_.cellEnd(c) - mesh_.cellBegin(c);
        for (label i = mesh_.cellBegin(c); i < mesh_.cellEnd(c); ++i)
        {
            xc += mesh_.inPlane(xv[cv[i]]);
        }
        xc /= scalar(n);
        scalar R = 0;
        for (label i = mesh_.cellBegin(c); i < mesh_.cellEnd(c); ++i)
        {
            R = max(R, mag(mesh_.inPlane(xv[cv[i]]) - xc));
        }
        centre[c] = xc;
        radius[c] = dHat_ + R;
        rMax = max(rMax, radius[c]);
    }

    cellStart_.setSize(nCells + 1);
    cellStart_ = 0;
    cellCentre_ = centre;
    cellDistance_.setSize(nCells);
    cellDistance_ = GREAT;
    cellFaces_.clear();
    if (faces_.empty()) return;

    // Bins over the faces' box grown by the largest search radius
    boundBox bb;
    for (const face& f : faces_)
    {
        bb.add(f.a); bb.add(f.b); bb.add(f.c);
    }
    bb.min() -= vector::uniform(rMax);
    bb.max() += vector::uniform(rMax);
    for (label d = 0; d < 3; ++d)
    {
        if (mesh_.offAxes()(d, d) > 0)
        {
            bb.min()[d] = -1;
            bb.max()[d] = 1;
        }
    }
    const label maxBins = 64;
    FixedList<label, 3> nb;
    vector binSize;
    for (label d = 0; d < 3; ++d)
    {
        const scalar ext = bb.max()[d] - bb.min()[d];
        nb[d] = max(label(1), min(maxBins, label(ext/rMax)));
        binSize[d] = ext/nb[d];
    }
    auto binRange = [&](const vector& lo, const vector& hi, FixedList<label, 6>& r)
    {
        for (label d = 0; d < 3; ++d)
        {
            r[d] = max(label(0), min(nb[d] - 1, label((lo[d] - bb.min()[d])/binSize[d])));
            r[3 + d] = max(label(0), min(nb[d] - 1, label((hi[d] - bb.min()[d])/binSize[d])));
        }
    };

    const label nBins = nb[0]*nb[1]*nb[2];
    labelList binStart(nBins + 1, Zero);
    FixedList<label, 6> r;
    for (label pass = 0; pass < 2; ++pass)
    {
        labelList fill;
        if (pass == 1)
        {
            for (label b = 0; b < nBins; ++b) binStart[b + 1] += binStart[b];
            fill = labelList(SubList<label>(binStart, nBins));
        }
        labelList binFaces(pass == 1 ? binStart[nBins] : 0);
        forAll(faces_, fi)
        {
            const face& f = faces_[fi];
            vector lo = min(min(f.a, f.b), f.c);
            vector hi = max(max(f.a, f.b), f.c);
            binRange(lo, hi, r);
            for (label i = r[0]; i <= r[3]; ++i)
            for (label j = r[1]; j <= r[4]; ++j)
            for (label k = r[2]; k <= r[5]; ++k)
            {
                const label b = i + nb[0]*(j + nb[1]*k);
                if (pass == 0) ++binStart[b + 1];
                else binFaces[fill[b]++] = fi;
            }
        }
        if (pass == 0) continue;

        // Each cell: the faces of the bins its search ball meets, within
        // the ball (a face seen in several bins is taken once)
        labelList stamp(faces_.size(), label(-1));
        DynamicList<label> list;
        DynamicList<label> found;
        for (label c = 0; c < nCells; ++c)
        {
            const vector& xc = centre[c];
            const scalar R = radius[c];
            binRange(xc - vector::uniform(R), xc + vector::uniform(R), r);
            found.clear();
            for (label i = r[0]; i <= r[3]; ++i)
            for (label j = r[1]; j <= r[4]; ++j)
            for (label k = r[2]; k <= r[5]; ++k)
            {
                const label b = i + nb[0]*(j + nb[1]*k);
                for (label q = binStart[b]; q < binStart[b + 1]; ++q)
                {
                    const label fi = binFaces[q];
                    if (stamp[fi] == c) continue;
                    stamp[fi] = c;
                    if (magSqr(nearest(faces_[fi], xc) - xc) <= R*R)
                    {
                        found.append(fi);
                    }
                }
            }
            std::sort(found.begin(), found.end());
            scalar dc2 = GREAT;
            for (const label fi : found)
            {
                dc2 = min(dc2, magSqr(nearest(faces_[fi], xc) - xc));
            }
            cellDistance_[c] = std::sqrt(dc2);
            list.append(found);
            cellStart_[c + 1] = list.size();
        }
        cellFaces_.transfer(list);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::barrierContact::barrierContact
(
    const polyMesh& mesh,
    const mpmMeshView& view,
    const dictionary& dict,
    const mpmParallel* par
)
:
    mesh_(view),
    dHat_(0),
    stiffness_(1),
    friction_(0),
    epsV_(1e-3),
    minDistance_(GREAT),
    nWithin_(0),
    nExamined_(0),
    forceTime_(0),
    nForceCalls_(0),
    frictionWork_(0),
    nWithinSum_(0),
    nExaminedSum_(0)
{
    using namespace dictionaryChecks;
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    const faceZoneMesh& fzm = mesh.faceZones();
    const bool hasPatches = dict.found("patches", keyType::LITERAL);
    const bool hasZones = dict.found("zones", keyType::LITERAL);

    // The patches, checked
    wordList allowed;
    for (const polyPatch& pp : pbm)
    {
        if (!isA<emptyPolyPatch>(pp) && !isA<processorPolyPatch>(pp))
        {
            allowed.append(pp.name());
        }
    }
    OStringStream allowedText;
    allowedText << "a list of boundary patches of the mesh (not empty or"
        << " processor): " << allowed;
    OStringStream allowedZones;
    allowedZones << "a list of faceZones of the mesh: " << fzm.names();
    if (!hasPatches && !hasZones)
    {
        missingEntry
        (
            dict, "patches",
            allowedText.str() + "; or 'zones', " + allowedZones.str()
        );
    }
    if (hasPatches || !hasZones)
    {
        patchNames_ = getAs<wordList>(dict, "patches", allowedText.str());
    }
    if (hasZones)
    {
        zoneNames_ = getAs<wordList>(dict, "zones", allowedZones.str());
    }
    if (patchNames_.empty() && zoneNames_.empty())
    {
        if (hasZones)
        {
            badEntry(dict, "zones", "()", allowedZones.str());
        }
        badEntry(dict, "patches", "()", allowedText.str());
    }
    labelList patchIDs(patchNames_.size());
    forAll(patchNames_, k)
    {
        const label id = pbm.findPatchID(patchNames_[k]);
        if
        (
            id < 0 || isA<emptyPolyPatch>(pbm[id])
         || isA<processorPolyPatch>(pbm[id])
        )
        {
            badEntry(dict, "patches", patchNames_[k], allowedText.str());
        }
        patchIDs[k] = id;
    }
    labelList zoneIDs(zoneNames_.size());
    forAll(zoneNames_, z)
    {
        const label id = fzm.findZoneID(zoneNames_[z]);
        if (id < 0)
        {
            badEntry(dict, "zones", zoneNames_[z], allowedZones.str());
        }
        zoneIDs[z] = id;
    }

    // This rank's faces: a, b, c, outward normal per face, and the surface
    const bool twoD = (view.dim() == 2);
    const pointField& pts = mesh.points();
    List<vector> local;
    labelList localPatch;
    DynamicList<vector> dl;
    DynamicList<label> dp;
    auto addFace = [&](const Foam::face& f, const vector& S, const label k)
    {
        const vector n = S/max(mag(S), VSMALL);
        if (twoD)
        {
            // The face's trace in the solution plane: its two points
            // farthest apart once projected
            scalar best = -1;
            vector a(Zero), b(Zero);
            forAll(f, m)
            {
                for (label q = m + 1; q < f.size(); ++q)
                {
                    const vector pm = view.inPlane(pts[f[m]]);
                    const vector pq = view.inPlane(pts[f[q]]);
                    if (magSqr(pq - pm) > best)
                    {
                        best = magSqr(pq - pm);
                        a = pm;
                        b = pq;
                    }
                }
            }
            dl.append(a); dl.append(b); dl.append(b);
            dl.append(view.inPlane(n));
            dp.append(k);
        }
        else
        {
            for (label m = 1; m + 1 < f.size(); ++m)
            {
                dl.append(pts[f[0]]);
                dl.append(pts[f[m]]);
                dl.append(pts[f[m + 1]]);
                dl.append(n);
                dp.append(k);
            }
        }
    };
    forAll(patchIDs, k)
    {
        const polyPatch& pp = pbm[patchIDs[k]];
        const vectorField Sf(pp.faceAreas());
        forAll(pp, i)
        {
            addFace(pp[i], Sf[i], k);
        }
    }
    forAll(zoneIDs, z)
    {
        const label k = patchNames_.size() + z;
        for (const label fi : fzm[zoneIDs[z]])
        {
            if (!mesh.isInternalFace(fi))
            {
                // A boundary face: not an empty one; a processor face
                // from its owner rank only (the ranks gather the faces)
                const polyPatch& pp = pbm[pbm.whichPatch(fi)];
                if (isA<emptyPolyPatch>(pp)) continue;
                const processorPolyPatch* proc =
                    isA<processorPolyPatch>(pp);
                if (proc && !proc->owner()) continue;
            }
            addFace(mesh.faces()[fi], mesh.faceAreas()[fi], k);
        }
    }
    local.transfer(dl);
    localPatch.transfer(dp);

    if (par)
    {
        // Every rank's faces on every rank
        List<List<vector>> allPts(Pstream::nProcs());
        List<labelList> allPatch(Pstream::nProcs());
        allPts[Pstream::myProcNo()] = local;
        allPatch[Pstream::myProcNo()] = localPatch;
        Pstream::gatherList(allPts);
        Pstream::scatterList(allPts);
        Pstream::gatherList(allPatch);
        Pstream::scatterList(allPatch);
        local.clear();
        localPatch.clear();
        DynamicList<vector> al;
        DynamicList<label> ap;
        forAll(allPts, r)
        {
            al.append(allPts[r]);
            ap.append(allPatch[r]);
        }
        local.transfer(al);
        localPatch.transfer(ap);
    }

    faces_.setSize(localPatch.size());
    forAll(faces_, i)
    {
        face& f = faces_[i];
        f.a = local[4*i];
        f.b = local[4*i + 1];
        f.c = local[4*i + 2];
        f.nOut = local[4*i + 3];
        f.patch = localPatch[i];
        f.segment = twoD;
    }
    readSettings(dict, meanEdge(faces_));
    buildCellFaces();

    Info<< "Barrier contact on patches " << patchNames_;
    if (zoneNames_.size())
    {
        Info<< " and faceZones " << zoneNames_;
    }
    Info<< ": " << faces_.size() << (twoD ? " segments" : " triangles") << ", dHat "
        << dHat_ << " m, stiffness " << stiffness_ << " (kappa_p = stiffness"
        << " E V0_p/dHat^2), friction " << friction_ << ", epsV " << epsV_
        << " m/s; " << returnReduce(nContactCells(), sumOp<label>())
        << " cells within reach" << nl;
}


Foam::barrierContact::barrierContact
(
    const mpmMeshView& view,
    const List<face>& faces,
    const wordList& patchNames,
    const dictionary& dict,
    const wordList& zoneNames
)
:
    mesh_(view),
    patchNames_(patchNames),
    zoneNames_(zoneNames),
    faces_(faces),
    dHat_(0),
    stiffness_(1),
    friction_(0),
    epsV_(1e-3),
    minDistance_(GREAT),
    nWithin_(0),
    nExamined_(0),
    forceTime_(0),
    nForceCalls_(0),
    frictionWork_(0),
    nWithinSum_(0),
    nExaminedSum_(0)
{
    readSettings(dict, meanEdge(faces_));
    buildCellFaces();
}


// ************************************************************************* //
