/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "solidLattice.H"
#include "bspline2Basis.H"
#include "mathematicalConstants.H"
#include "error.H"

// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * * //

void Foam::solidLattice::build()
{
    scale_ = 1;
    for (label d = 0; d < 3; ++d)
    {
        nv_[d] = lat_.active(d) ? lat_.n(d) + 1 + 2*sh_[d] : 1;
        if (!lat_.active(d)) scale_ *= lat_.dx(d);
    }
    vertexAt_.assign(nv_[0]*nv_[1]*nv_[2], -1);
    const List<vector>& xv = view_.vertices();
    forAll(xv, v)
    {
        label ijk[3] = {0, 0, 0};
        bool outside = false;
        for (label d = 0; d < 3; ++d)
        {
            if (!lat_.active(d) || d >= view_.dim()) continue;
            const scalar s =
                (xv[v][d] - lat_.origin()[d])/lat_.dx(d) + sh_[d];
            ijk[d] = label(std::lround(s));
            if (ring_.valid() && mag(s - ijk[d]) <= 1e-6)
            {
                // a halo vertex beyond the grown box: no face's node
                if (ijk[d] < 0 || ijk[d] >= nv_[d]) outside = true;
                continue;
            }
            if (mag(s - ijk[d]) > 1e-6 || ijk[d] < 0 || ijk[d] >= nv_[d])
            {
                FatalErrorInFunction
                    << "MPM vertex " << v << " at " << xv[v]
                    << " is not a vertex of the gas lattice (origin "
                    << lat_.origin() << ", spacing " << lat_.dx(d)
                    << " along direction " << d << ")" << exit(FatalError);
            }
        }
        if (outside) continue;
        vertexAt_[ijk[0] + nv_[0]*(ijk[1] + nv_[1]*ijk[2])] = v;
    }

    for (label d = 0; d < 3; ++d)
    {
        faces_[d].clear();
        nodes_[d].clear();
        weights_[d].clear();
        if (!lat_.active(d)) continue;
        faceSlot_[d].assign(lat_.nFaces(d), -1);
        faceMark_[d].assign(lat_.nFaces(d), 0);
        touchedFaces_[d].clear();
        const label st = lat_.stride(d);
        for (const auto& s : lat_.segments(d))
        {
            // Parallel: the processor faces at the segment's ends too
            const bool lowProc = ring_.valid() && s.lowGhost >= 0;
            const bool highProc = ring_.valid() && s.highGhost >= 0;
            const label m0 = lowProc ? 0 : 1;
            const label m1 = highProc ? s.length + 1 : s.length;
            for (label m = m0; m < m1; ++m)
            {
                face fc;
                fc.f = s.faceOffset + m;
                fc.l = m > 0 ? s.start + (m - 1)*st : -1;
                fc.r = m < s.length ? s.start + m*st : -1;
                fc.slot = m == 0 ? s.lowGhost : (m == s.length ? s.highGhost : -1);
                fc.node0 = label(nodes_[d].size());

                // (3.32) B-spline weights at the face centre: integer
                // coordinate a along d, half-integers across (vertex
                // coordinates, shifted by the ring in parallel)
                label c[3];
                if (fc.r >= 0)
                {
                    lat_.ijk(fc.r, c[0], c[1], c[2]);
                }
                else
                {
                    lat_.ijk(fc.l, c[0], c[1], c[2]);
                    ++c[d];
                }
                for (label e = 0; e < 3; ++e) c[e] += sh_[e];
                label lo[3], cnt[3];
                double w[3][3];
                for (label e = 0; e < 3; ++e)
                {
                    if (!lat_.active(e))
                    {
                        lo[e] = 0; cnt[e] = 1; w[e][0] = 1;
                    }
                    else if (e == d)
                    {
                        lo[e] = c[e] - 1; cnt[e] = 3;
                        w[e][0] = bspline2::N(1);
                        w[e][1] = bspline2::N(0);
                        w[e][2] = bspline2::N(-1);
                    }
                    else
                    {
                        lo[e] = c[e]; cnt[e] = 2;
                        w[e][0] = bspline2::N(0.5);
                        w[e][1] = bspline2::N(-0.5);
                    }
                }
                for (label a = 0; a < cnt[0]; ++a)
                for (label b = 0; b < cnt[1]; ++b)
                for (label k = 0; k < cnt[2]; ++k)
                {
                    const label i = lo[0] + a, j = lo[1] + b, kk = lo[2] + k;
                    if
                    (
                        i < 0 || j < 0 || kk < 0
                     || i >= nv_[0] || j >= nv_[1] || kk >= nv_[2]
                    )
                    {
                        continue;
                    }
                    const label v = vertexAt_[i + nv_[0]*(j + nv_[1]*kk)];
                    if (v < 0) continue;
                    nodes_[d].push_back(v);
                    weights_[d].push_back(w[0][a]*w[1][b]*w[2][k]);
                }
                fc.nNodes = label(nodes_[d].size()) - fc.node0;
                faceSlot_[d][fc.f] = label(faces_[d].size());
                faces_[d].push_back(fc);
            }
        }
        const label nf = lat_.nFaces(d);
        Vface_[d].assign(nf, 0.0);
        R_[d].assign(nf, 0.0);
        open_[d].assign(nf, 1.0);
    }
    const label nLat = lat_.nLattice();
    Vcell_.assign(nLat, 0.0);
    pg_.assign(nLat, 0.0);
    Kg_.assign(nLat, 0.0);
    cellMark_.assign(nLat, 0);
    touchedCells_.clear();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidLattice::solidLattice
(
    const cartesianMesh& lattice,
    const mpmMeshView& view,
    const bool parallel
)
:
    lat_(lattice),
    view_(view)
{
    if (parallel && Pstream::parRun())
    {
        ring_.reset(new latticeRing(lattice));
        for (label d = 0; d < 3; ++d) sh_[d] = ring_->sh(d);
        VcellE_.assign(ring_->nCellsE(), 0.0);
        pgE_.assign(ring_->nCellsE(), 0.0);
        KgE_.assign(ring_->nCellsE(), 0.0);
        keyE_.assign(ring_->nCellsE(), GREAT);
        for (label d = 0; d < 3; ++d)
        {
            VfaceE_[d].assign(ring_->nFacesE(d), 0.0);
        }
        // Which cells of the grown box are mesh cells of some rank (the
        // deposit's hats give nothing to the others, as in serial)
        inMeshE_.assign(ring_->nCellsE(), 0.0);
        for (label i = 0; i < lat_.nLattice(); ++i)
        {
            if (lat_.cellAt()[i] >= 0) inMeshE_[ring_->cellOf(i)] = 1;
        }
        {
            std::vector<double>* noFaces[3] = {nullptr, nullptr, nullptr};
            ring_->combine({&inMeshE_}, {false}, noFaces);
        }
        // The neighbour cell of each ghost slot in the grown box
        phiSlot_.assign(lat_.nGhostSlots(), 0.0);
        slotCellE_.assign(lat_.nGhostSlots(), -1);
        for (label d = 0; d < 3; ++d)
        {
            if (!lat_.active(d)) continue;
            const label st = lat_.stride(d);
            for (const auto& s : lat_.segments(d))
            {
                if (s.lowGhost >= 0)
                {
                    slotCellE_[s.lowGhost] =
                        ring_->cellOf(s.start) - ring_->strideE(d);
                }
                if (s.highGhost >= 0)
                {
                    slotCellE_[s.highGhost] =
                        ring_->cellOf(s.start + (s.length - 1)*st)
                      + ring_->strideE(d);
                }
            }
        }
    }
    build();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::solidLattice::resetTouched()
{
    for (const label i : touchedCells_)
    {
        Vcell_[i] = 0;
        pg_[i] = 0;
        Kg_[i] = 0;
        cellMark_[i] = 0;
    }
    touchedCells_.clear();
    for (label d = 0; d < 3; ++d)
    {
        for (const label f : touchedFaces_[d])
        {
            Vface_[d][f] = 0;
            R_[d][f] = 0;
            open_[d][f] = 1;
            faceMark_[d][f] = 0;
        }
        touchedFaces_[d].clear();
    }
}


void Foam::solidLattice::deposit
(
    const mpmParticles& P,
    const UList<scalar>& pgp,
    const UList<scalar>& Kgp
)
{
    if (ring_.valid())
    {
        depositParallel(P, pgp, Kgp);
        reflectiveShares();
        return;
    }
    const label nLat = lat_.nLattice();

    resetTouched();
    const auto& cellAt = lat_.cellAt();
    const label n[3] = {lat_.n(0), lat_.n(1), lat_.n(2)};

    forAll(P.x, p)
    {
        const scalar Vp = scale_*P.V[p];
        double s[3];
        label c0[3];
        double tc[3];
        for (label e = 0; e < 3; ++e)
        {
            if (!lat_.active(e)) { c0[e] = 0; tc[e] = 0; s[e] = 0; continue; }
            s[e] = (P.x[p][e] - lat_.origin()[e])/lat_.dx(e);
            hat(s[e] - 0.5, n[e], c0[e], tc[e]);
        }

        // Cells.  A hat corner on a lattice cell outside the mesh (a wall
        // inside the lattice's box: a bore, a step) gives its share to
        // the corners in the mesh, as the hat is clamped at the lattice's
        // ends: no volume is lost, a body that fills a channel covers the
        // cells at its walls wholly (else 1/8 of them stayed open to the
        // gas, and the pressure work there made energy)
        label cIdx[8];
        double cW[8];
        double lost = 0;
        for (label a = 0; a < 2; ++a)
        for (label b = 0; b < 2; ++b)
        for (label k = 0; k < 2; ++k)
        {
            const label q = 4*a + 2*b + k;
            cW[q] =
                (a ? tc[0] : 1 - tc[0])*(b ? tc[1] : 1 - tc[1])
               *(k ? tc[2] : 1 - tc[2]);
            cIdx[q] = (c0[0] + a) + n[0]*((c0[1] + b) + n[1]*(c0[2] + k));
            if (cW[q] > 0 && (cIdx[q] >= nLat || cellAt[cIdx[q]] < 0))
            {
                lost += cW[q];
                cW[q] = 0;
            }
        }
        if (lost > 0 && lost < 1)
        {
            for (double& w : cW) w /= 1 - lost;
        }
        for (label q = 0; q < 8; ++q)
        {
            const double w = cW[q];
            if (w <= 0) continue;
            const label idx = cIdx[q];
            if (!cellMark_[idx])
            {
                cellMark_[idx] = 1;
                touchedCells_.push_back(idx);
            }
            Vcell_[idx] += w*Vp;
            pg_[idx] += w*Vp*pgp[p];
            Kg_[idx] += w*Vp*Kgp[p];
        }

        // Faces of each direction: hat at integers along d
        for (label d = 0; d < 3; ++d)
        {
            if (!lat_.active(d)) continue;
            label f0[3];
            double tf[3];
            for (label e = 0; e < 3; ++e) { f0[e] = c0[e]; tf[e] = tc[e]; }
            hat(s[d], n[d] + 1, f0[d], tf[d]);
            // (as the cells: the shares of corners outside the mesh across
            // the face's line go to those in it; along d, the face at a
            // wall inside the box is the high face of the cell below it)
            label fIdx[8];
            bool fHigh[8];
            double fW[8];
            double fLost = 0;
            for (label a = 0; a < 2; ++a)
            for (label b = 0; b < 2; ++b)
            for (label k = 0; k < 2; ++k)
            {
                const label q = 4*a + 2*b + k;
                fW[q] =
                    (a ? tf[0] : 1 - tf[0])*(b ? tf[1] : 1 - tf[1])
                   *(k ? tf[2] : 1 - tf[2]);
                label ijk[3] = {f0[0] + a, f0[1] + b, f0[2] + k};
                // The face at integer a along d is the low face of cell a,
                // or the high face of cell a - 1 at the far end
                bool high = false;
                if (ijk[d] >= n[d]) { ijk[d] = n[d] - 1; high = true; }
                label idx = ijk[0] + n[0]*(ijk[1] + n[1]*ijk[2]);
                if (!high && ijk[d] > 0 && idx < nLat && cellAt[idx] < 0)
                {
                    const label below = idx - lat_.stride(d);
                    if (cellAt[below] >= 0) { idx = below; high = true; }
                }
                fIdx[q] = idx;
                fHigh[q] = high;
                if (fW[q] > 0 && (idx >= nLat || cellAt[idx] < 0))
                {
                    fLost += fW[q];
                    fW[q] = 0;
                }
            }
            if (fLost > 0 && fLost < 1)
            {
                for (double& w : fW) w /= 1 - fLost;
            }
            for (label q = 0; q < 8; ++q)
            {
                const double w = fW[q];
                if (w <= 0) continue;
                const label idx = fIdx[q];
                const bool high = fHigh[q];
                const label f = lat_.lowFaceOf(d)[idx] + (high ? 1 : 0);
                if (!faceMark_[d][f])
                {
                    faceMark_[d][f] = 1;
                    touchedFaces_[d].push_back(f);
                }
                Vface_[d][f] += w*Vp;
            }
        }
    }

    reflectiveShares();
}


void Foam::solidLattice::reflectiveShares()
{
    // (3.2.3) reflective share of each face
    const scalar Vc = lat_.cellVolume();
    const label D = lat_.nDims();
    nInterfaceFaces_ = 0;
    for (label d = 0; d < 3; ++d)
    {
        if (!lat_.active(d)) continue;
        scalar dxt = 1;     // 2D: the face's width
        for (label e = 0; e < 3; ++e)
        {
            if (e != d && lat_.active(e)) dxt = lat_.dx(e);
        }
        const scalar Af = Vc/lat_.dx(d);
        for (const label f : touchedFaces_[d])
        {
            const double frac = Vface_[d][f]/Vc;
            double R = 0;
            if (frac > 0)
            {
                if (D == 1)
                {
                    R = frac;
                }
                else if (D == 2)
                {
                    const double A2 = frac*lat_.dx(d)*dxt;
                    R = 2*std::sqrt(A2/constant::mathematical::pi)/dxt;
                }
                else
                {
                    const double r = std::cbrt
                    (
                        3*frac*Vc/(4*constant::mathematical::pi)
                    );
                    R = constant::mathematical::pi*r*r/Af;
                }
                if (R > 1) R = 1;
                if (R < 1) ++nInterfaceFaces_;
            }
            R_[d][f] = R;
            open_[d][f] = 1 - R;
        }
    }
    nSolidCells_ = 0;
    for (const label i : touchedCells_)
    {
        if (Vcell_[i] > 0.5*Vc) ++nSolidCells_;
    }
}


// ************************************************************************* //
