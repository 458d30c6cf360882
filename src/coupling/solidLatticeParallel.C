/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "solidLattice.H"
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * * //

// The deposit of solidLattice::deposit on the rank's grown box, summed over
// the ranks (latticeRing), then copied to the rank's cells and faces
void Foam::solidLattice::depositParallel
(
    const mpmParticles& P,
    const UList<scalar>& pgp,
    const UList<scalar>& Kgp
)
{
    const latticeRing& ring = ring_();

    // Reset the lattice's touched cells and faces, and the grown box
    resetTouched();
    std::fill(VcellE_.begin(), VcellE_.end(), 0.0);
    std::fill(pgE_.begin(), pgE_.end(), 0.0);
    std::fill(KgE_.begin(), KgE_.end(), 0.0);
    std::fill(keyE_.begin(), keyE_.end(), 1e300);
    for (label d = 0; d < 3; ++d)
    {
        std::fill(VfaceE_[d].begin(), VfaceE_[d].end(), 0.0);
    }

    // Linear hats (hat) in the global lattice's coordinates (the serial
    // run's weights, bit for bit), clamped at its ends as the serial
    // deposit; then shifted to the grown box
    const point& o = ring.globalOrigin();
    label N[3], shift[3];
    for (label e = 0; e < 3; ++e)
    {
        N[e] = ring.N(e);
        shift[e] = ring.off(e) - sh_[e];
    }
    forAll(P.x, p)
    {
        const scalar Vp = scale_*P.V[p];
        // The serial run's particle order: by material, then id
        const double key =
            8.0*(double(P.material[p])*1099511627776.0 + double(P.id[p]));
        double s[3];
        label c0[3];
        double tc[3];
        for (label e = 0; e < 3; ++e)
        {
            if (!lat_.active(e)) { c0[e] = 0; tc[e] = 0; s[e] = 0; continue; }
            s[e] = (P.x[p][e] - o[e])/lat_.dx(e);
            hat(s[e] - 0.5, N[e], c0[e], tc[e]);
        }

        // (the corners outside the mesh give their shares to the others,
        // as in the serial deposit)
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
            cIdx[q] = ring.cellE
            (
                c0[0] + a - shift[0], c0[1] + b - shift[1],
                c0[2] + k - shift[2]
            );
            if (cW[q] > 0 && !(inMeshE_[cIdx[q]] > 0))
            {
                lost += cW[q];
                cW[q] = 0;
            }
        }
        if (lost > 0 && lost < 1)
        {
            for (double& w : cW) w /= 1 - lost;
        }
        for (label a = 0; a < 2; ++a)
        for (label b = 0; b < 2; ++b)
        for (label k = 0; k < 2; ++k)
        {
            const double w = cW[4*a + 2*b + k];
            if (w <= 0) continue;
            const label idx = cIdx[4*a + 2*b + k];
            VcellE_[idx] += w*Vp;
            pgE_[idx] += w*Vp*pgp[p];
            KgE_[idx] += w*Vp*Kgp[p];
            const double kc = key + 4*a + 2*b + k;
            if (kc < keyE_[idx]) keyE_[idx] = kc;
        }

        for (label d = 0; d < 3; ++d)
        {
            if (!lat_.active(d)) continue;
            label f0[3];
            double tf[3];
            for (label e = 0; e < 3; ++e) { f0[e] = c0[e]; tf[e] = tc[e]; }
            // faces 0..N along d
            hat(s[d], N[d] + 1, f0[d], tf[d]);
            // (a face is in the mesh if a cell on either side is)
            label fIdx[8];
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
                label g[3] =
                {
                    f0[0] + a - shift[0], f0[1] + b - shift[1],
                    f0[2] + k - shift[2]
                };
                fIdx[q] = ring.faceE(d, g[0], g[1], g[2]);
                if (!(fW[q] > 0)) continue;
                bool in = false;
                if (g[d] < ring.nE(d))
                {
                    in = inMeshE_[ring.cellE(g[0], g[1], g[2])] > 0;
                }
                if (!in && g[d] > 0)
                {
                    --g[d];
                    in = inMeshE_[ring.cellE(g[0], g[1], g[2])] > 0;
                }
                if (!in)
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
                if (fW[q] <= 0) continue;
                VfaceE_[d][fIdx[q]] += fW[q]*Vp;
            }
        }
    }

    // Sum the copies over the ranks
    std::vector<double>* faces[3] = {nullptr, nullptr, nullptr};
    for (label d = 0; d < 3; ++d)
    {
        if (lat_.active(d)) faces[d] = &VfaceE_[d];
    }
    ring.combine
    (
        {&VcellE_, &pgE_, &KgE_, &keyE_}, {false, false, false, true}, faces
    );

    // The rank's cells, in the serial run's order of first touch
    std::vector<std::pair<double, label>> order;
    const label nLat = lat_.nLattice();
    for (label i = 0; i < nLat; ++i)
    {
        const label e = ring.cellOf(i);
        if (keyE_[e] < 1e300)
        {
            order.emplace_back(keyE_[e], i);
            Vcell_[i] = VcellE_[e];
            pg_[i] = pgE_[e];
            Kg_[i] = KgE_[e];
            cellMark_[i] = 1;
        }
    }
    std::sort(order.begin(), order.end());
    for (const auto& o : order) touchedCells_.push_back(o.second);

    // Their faces
    for (label d = 0; d < 3; ++d)
    {
        if (!lat_.active(d)) continue;
        const auto& lowFace = lat_.lowFaceOf(d);
        for (label i = 0; i < nLat; ++i)
        {
            label c[3];
            lat_.ijk(i, c[0], c[1], c[2]);
            for (label e = 0; e < 3; ++e) c[e] += sh_[e];
            for (label h = 0; h < 2; ++h)
            {
                const label f = lowFace[i] + h;
                if (faceMark_[d][f]) continue;
                c[d] += h;
                const double V = VfaceE_[d][ring.faceE(d, c[0], c[1], c[2])];
                c[d] -= h;
                if (V > 0)
                {
                    faceMark_[d][f] = 1;
                    touchedFaces_[d].push_back(f);
                    Vface_[d][f] = V;
                }
            }
        }
    }

    // The neighbour ranks' cells across the processor faces
    const scalar Vc = lat_.cellVolume();
    for (size_t j = 0; j < phiSlot_.size(); ++j)
    {
        const double a = VcellE_[slotCellE_[j]]/Vc;
        phiSlot_[j] = a < 1 ? a : 1;
    }
}


// ************************************************************************* //
