/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "eulerOperator.H"
#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::eulerOperator::eulerOperator
(
    const cartesianMesh& mesh,
    const idealGas& gas,
    const gasFluxScheme& scheme,
    const PtrList<gasBoundary>& bcs
)
:
    mesh_(mesh),
    gas_(gas),
    scheme_(scheme),
    bcs_(bcs),
    G_(scheme.nGhost())
{
    label maxL = 0;
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        for (auto& a : F_[d]) a.assign(mesh_.nFaces(d), 0.0);
        for (const auto& s : mesh_.segments(d))
        {
            maxL = std::max(maxL, s.length);
            if
            (
                s.length < G_
             && (s.lowGhost >= 0 || s.highGhost >= 0)
            )
            {
                FatalErrorInFunction
                    << "A subdomain of this parallel run is "
                    << s.length << " cells thick along " << "xyz"[d]
                    << " (line at cell " << mesh_.cellAt()[s.start]
                    << "); the scheme " << scheme_.type() << " needs "
                    << G_ << " cells on each side of a processor boundary."
                    << nl << "    Decompose with fewer subdomains along "
                    << "xyz"[d] << " (method simple or hierarchical, n in"
                    << " system/decomposeParDict) so that each has at least "
                    << G_ << " cells along it" << exit(FatalError);
            }
            if (s.length < G_)
            {
                const bool periodic =
                    bcs_[s.lowPatch].kindOf() == gasBoundary::kind::periodic;
                if (periodic)
                {
                    FatalErrorInFunction
                        << "A periodic line along " << "xyz"[d] << " has "
                        << s.length << " cells; the scheme needs at least "
                        << G_ << exit(FatalError);
                }
            }
        }
    }
    for (auto& b : buf_) b.assign(maxL + 2*G_, 0.0);
    for (auto& b : Fline_) b.assign(maxL + 1, 0.0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::gasLine Foam::eulerOperator::gather
(
    const gasState& U,
    label d,
    const cartesianMesh::segment& s,
    label nGhost,
    bool advective
)
{
    gasLine line;
    for (int c = 0; c < 5; ++c) line.q[c] = buf_[c].data();
    line.L = s.length;
    line.G = nGhost;
    line.normal = d;
    line.gamma = gas_.gamma();
    line.advective = advective;

    const label st = mesh_.stride(d);
    for (int c = 0; c < 5; ++c)
    {
        const double* src = U.q[c].data() + s.start;
        double* dst = line.q[c] + nGhost;
        for (label m = 0; m < s.length; ++m) dst[m] = src[m*st];
    }

    // Short non-periodic lines: the mirror/extrapolation partners beyond
    // the line repeat its last cell
    if (s.lowGhost >= 0) processorGhosts(line, s.lowGhost, false);
    else bcs_[s.lowPatch].fillGhosts(line, false);
    if (s.highGhost >= 0) processorGhosts(line, s.highGhost, true);
    else bcs_[s.highPatch].fillGhosts(line, true);
    return line;
}


void Foam::eulerOperator::processorGhosts
(
    const gasLine& line,
    label slot,
    bool high
) const
{
    const label G = line.G, L = line.L;
    for (label k = 0; k < G; ++k)
    {
        const label g = high ? G + L + k : G - 1 - k;
        const double* src = ghost_.data() + (slot*G_ + k)*5;
        for (int c = 0; c < 5; ++c) line.q[c][g] = src[c];
    }
}


void Foam::eulerOperator::firstOrderFace
(
    const gasLine& line,
    const cartesianMesh::segment& s,
    label m
)
{
    double qL[5], qR[5], Ff[5];
    for (int c = 0; c < 5; ++c)
    {
        qL[c] = line.q[c][line.G + m - 1];
        qR[c] = line.q[c][line.G + m];
    }
    gasFluxScheme::firstOrderFlux
    (
        qL, qR, line.normal, line.gamma, line.advective, Ff
    );
    for (int c = 0; c < 5; ++c)
    {
        F_[line.normal][c][s.faceOffset + m] = Ff[c];
    }
}


void Foam::eulerOperator::wallFace(label d, label f)
{
    F_[d][0][f] = 0;
    F_[d][4][f] = 0;
    for (label t = 0; t < 3; ++t)
    {
        if (t != d) F_[d][1 + t][f] = 0;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::eulerOperator::computeFluxes(const gasState& U, bool advective)
{
    if (Pstream::parRun())
    {
        mesh_.exchangeGhosts(U.q, G_, ghost_);
    }
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        for (const auto& s : mesh_.segments(d))
        {
            if (s.length < G_)
            {
                // Too short for the scheme's ghosts: first order
                const gasLine line = gather(U, d, s, 1, advective);
                for (label m = 0; m <= s.length; ++m)
                {
                    firstOrderFace(line, s, m);
                }
            }
            else
            {
                const gasLine line = gather(U, d, s, G_, advective);
                double* F[5];
                for (int c = 0; c < 5; ++c)
                {
                    F[c] = F_[d][c].data() + s.faceOffset;
                }
                scheme_.lineFluxes(line, F);
            }
            if (bcs_[s.lowPatch].kindOf() == gasBoundary::kind::wall)
            {
                wallFace(d, s.faceOffset);
            }
            if (bcs_[s.highPatch].kindOf() == gasBoundary::kind::wall)
            {
                wallFace(d, s.faceOffset + s.length);
            }
        }
        if (open_[d])
        {
            for (const auto& s : mesh_.segments(d))
            {
                // (processor faces too: the coupling's faces across ranks)
                const label m0 = s.lowGhost >= 0 ? 0 : 1;
                const label m1 = s.highGhost >= 0 ? s.length + 1 : s.length;
                for (label m = m0; m < m1; ++m)
                {
                    blendFace(d, s.faceOffset + m);
                }
            }
        }
    }
}


void Foam::eulerOperator::boundaryFlux(double B[5]) const
{
    for (int c = 0; c < 5; ++c) B[c] = 0;
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const double A = mesh_.cellVolume()/mesh_.dx(d);
        for (const auto& s : mesh_.segments(d))
        {
            if (bcs_[s.lowPatch].kindOf() == gasBoundary::kind::periodic)
            {
                continue;
            }
            // (the line's out minus in first: equal end fluxes, as at
            // two walls in a gas at rest, cancel exactly)
            const label lo = s.faceOffset, hi = s.faceOffset + s.length;
            for (int c = 0; c < 5; ++c)
            {
                const double in = s.lowGhost < 0 ? F_[d][c][lo] : 0;
                const double out = s.highGhost < 0 ? F_[d][c][hi] : 0;
                B[c] += A*(out - in);
            }
        }
    }
}


void Foam::eulerOperator::firstOrderSlotFace
(
    const gasState& U,
    label slot,
    bool advective
)
{
    const label idx = mesh_.slotCell(slot);
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const label f0 = mesh_.lowFaceOf(d)[idx];
        const cartesianMesh::segment& s = mesh_.segmentOfFace(d, f0);
        const label m = f0 - s.faceOffset;
        label mf = -1;
        if (s.lowGhost == slot && m == 0) mf = 0;
        else if (s.highGhost == slot && m + 1 == s.length) mf = s.length;
        if (mf < 0) continue;
        const gasLine line = gather(U, d, s, 1, advective);
        firstOrderFace(line, s, mf);
        if (open_[d]) blendFace(d, s.faceOffset + mf);
    }
}


void Foam::eulerOperator::firstOrderFaces
(
    const gasState& U,
    label idx,
    bool advective
)
{
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const label f0 = mesh_.lowFaceOf(d)[idx];
        const cartesianMesh::segment& s = mesh_.segmentOfFace(d, f0);
        const label m = f0 - s.faceOffset;      // cell position in segment
        const gasLine line = gather(U, d, s, 1, advective);
        firstOrderFace(line, s, m);
        firstOrderFace(line, s, m + 1);
        if (open_[d])
        {
            if (m > 0 || s.lowGhost >= 0) blendFace(d, f0);
            if (m + 1 < s.length || s.highGhost >= 0) blendFace(d, f0 + 1);
        }
        if (m == 0 && bcs_[s.lowPatch].kindOf() == gasBoundary::kind::wall)
        {
            wallFace(d, s.faceOffset);
        }
        if
        (
            m == s.length - 1
         && bcs_[s.highPatch].kindOf() == gasBoundary::kind::wall
        )
        {
            wallFace(d, s.faceOffset + s.length);
        }
        // A periodic line's two end faces are one face
        if (bcs_[s.lowPatch].kindOf() == gasBoundary::kind::periodic)
        {
            if (m == 0)
            {
                for (int c = 0; c < 5; ++c)
                {
                    F_[d][c][s.faceOffset + s.length] =
                        F_[d][c][s.faceOffset];
                }
            }
            else if (m == s.length - 1)
            {
                for (int c = 0; c < 5; ++c)
                {
                    F_[d][c][s.faceOffset] =
                        F_[d][c][s.faceOffset + s.length];
                }
            }
        }
    }
}


// ************************************************************************* //
