/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "wallCorners.H"
#include <cmath>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::wallCorners::treatment>
Foam::wallCorners::treatmentNames
({
    { treatment::none, "none" },
    { treatment::entropyReset, "entropyReset" },
    { treatment::entropyTransfer, "entropyTransfer" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::wallCorners::wallCorners
(
    const cartesianMesh& mesh,
    const idealGas& gas,
    const PtrList<gasBoundary>& bcs,
    treatment t,
    label nReset,
    label nGhost
)
:
    mesh_(mesh),
    gas_(gas),
    bcs_(bcs),
    treatment_(t),
    nReset_(nReset > 0 ? nReset : nGhost)
{
    if (treatment_ != treatment::none)
    {
        findCorners();
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::wallCorners::wallSide(label idx, label d, int s) const
{
    const label low = mesh_.lowFaceOf(d)[idx];
    const label f = low + (s > 0 ? 1 : 0);
    const cartesianMesh::segment& seg = mesh_.segmentOfFace(d, low);
    if (s < 0 && f == seg.faceOffset)
    {
        return bcs_[seg.lowPatch].kindOf() == gasBoundary::kind::wall;
    }
    if (s > 0 && f == seg.faceOffset + seg.length)
    {
        return bcs_[seg.highPatch].kindOf() == gasBoundary::kind::wall;
    }
    return false;
}


void Foam::wallCorners::findCorners()
{
    const auto& cellAt = mesh_.cellAt();
    const label N = mesh_.nLattice();

    for (label D = 0; D < N; ++D)
    {
        if (cellAt[D] >= 0) continue;
        label ijk[3];
        mesh_.ijk(D, ijk[0], ijk[1], ijk[2]);
        // the lattice neighbour of D offset by o (-1 outside the lattice)
        auto at = [&](const int o[3])
        {
            label idx = 0;
            for (label d = 0; d < 3; ++d)
            {
                const label k = ijk[d] + o[d];
                if (k < 0 || k >= mesh_.n(d)) return label(-1);
                idx += k*mesh_.stride(d);
            }
            return cellAt[idx] >= 0 ? idx : label(-1);
        };
        for (label d1 = 0; d1 < 3; ++d1)
        {
            if (!mesh_.active(d1)) continue;
            for (label d2 = d1 + 1; d2 < 3; ++d2)
            {
                if (!mesh_.active(d2)) continue;
                for (const int s1 : {-1, 1})
                {
                    for (const int s2 : {-1, 1})
                    {
                        int oA[3] = {0, 0, 0}, oC[3] = {0, 0, 0};
                        int oB[3] = {0, 0, 0};
                        oA[d1] = s1;
                        oC[d2] = s2;
                        oB[d1] = s1;
                        oB[d2] = s2;
                        const label A = at(oA), B = at(oB), C = at(oC);
                        if (A < 0 || B < 0 || C < 0) continue;
                        if (!wallSide(A, d1, -s1) || !wallSide(C, d2, -s2))
                        {
                            continue;
                        }
                        corner k{A, B, C, d1, d2, s1, s2, {}, {}};
                        // The wall cells from A away from the edge (along
                        // -s2 e_d2, wall on side -s1 of d1), and from C
                        // (along -s1 e_d1, wall on side -s2 of d2)
                        for (label m = 0; m < nReset_; ++m)
                        {
                            int o[3] = {0, 0, 0};
                            o[d1] = s1;
                            o[d2] = -int(m)*s2;
                            const label X = at(o);
                            if (X < 0 || !wallSide(X, d1, -s1)) break;
                            k.wallA.push_back(X);
                        }
                        for (label m = 0; m < nReset_; ++m)
                        {
                            int o[3] = {0, 0, 0};
                            o[d1] = -int(m)*s1;
                            o[d2] = s2;
                            const label X = at(o);
                            if (X < 0 || !wallSide(X, d2, -s2)) break;
                            k.wallC.push_back(X);
                        }
                        corners_.push_back(k);
                    }
                }
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// Woodward-Colella-type corner reset (see the class description)
Foam::label Foam::wallCorners::correct
(
    gasState& U,
    scalar& dMass,
    scalar& dEnergy
) const
{
    const bool transfer = (treatment_ == treatment::entropyTransfer);
    if (treatment_ != treatment::entropyReset && !transfer) return 0;
    const double g = gas_.gamma();
    const scalar V = mesh_.cellVolume();
    auto pressure = [&](label i)
    {
        const double m2 =
            U.q[1][i]*U.q[1][i] + U.q[2][i]*U.q[2][i] + U.q[3][i]*U.q[3][i];
        return (g - 1)*(U.q[4][i] - 0.5*m2/U.q[0][i]);
    };

    label n = 0;
    for (const corner& k : corners_)
    {
        // Flow round the corner from A's wall to C's, or from C's to A's:
        // along the wall towards the edge in one and away from it in the
        // other (the edge is at -s1 e_d1/2 + s2 e_d2/2 from A and at
        // s1 e_d1/2 - s2 e_d2/2 from C)
        const double tA = k.s2*U.q[1 + k.d2][k.A];    // > 0: towards the edge
        const double tC = k.s1*U.q[1 + k.d1][k.C];

        // In 3-D only where the flow turns round the edge rather than runs
        // along it: the edge's direction carries less momentum than the
        // wall-tangential one in both cells
        const label e = 3 - k.d1 - k.d2;
        if
        (
            !(std::abs(tA) > std::abs(U.q[1 + e][k.A]))
         || !(std::abs(tC) > std::abs(U.q[1 + e][k.C]))
        )
        {
            continue;
        }

        label up;
        const std::vector<label>* down;
        label tDir;         // the downstream wall's tangential direction
        int away;           // and the sign pointing away from the edge
        if (tA > 0 && tC < 0)
        {
            up = k.A;
            down = &k.wallC;
            tDir = k.d1;
            away = -k.s1;
        }
        else if (tC > 0 && tA < 0)
        {
            up = k.C;
            down = &k.wallA;
            tDir = k.d2;
            away = -k.s2;
        }
        else
        {
            continue;
        }
        const double pUp = pressure(up);
        if (!(pUp > 0)) continue;
        const double Kup = pUp/std::pow(U.q[0][up], g);
        const double tUp = std::abs(up == k.A ? tA : tC)/U.q[0][up];

        // The downstream wall cells from the edge on, while the gas there
        // has expanded from the upstream cell's (p < p_up, and faster away
        // from the edge than the upstream gas comes towards it; not so in
        // dead water behind the edge) and carries more entropy
        const label nCells = transfer ? 1 : label(down->size());
        for (label m = 0; m < nCells; ++m)
        {
            const label i = (*down)[m];
            const double rho = U.q[0][i];
            const double p = pressure(i);
            if
            (
                !(away*U.q[1 + tDir][i]/rho > tUp) || !(p < pUp) || !(p > 0)
             || !(p/std::pow(rho, g) > Kup)
            )
            {
                break;
            }

            // Same p and total enthalpy H = (rho E + p)/rho, entropy Kup:
            //   rho' = (p/Kup)^(1/gamma),
            //   |u'|^2 = 2 (H - gamma p/((gamma - 1) rho')),
            //   direction of u kept, rho E' = rho' H - p
            const double H = (U.q[4][i] + p)/rho;
            const double rhoNew = std::pow(p/Kup, 1/g);
            const double hNew = g/(g - 1)*p/rhoNew;
            const double u2 =
                (
                    U.q[1][i]*U.q[1][i] + U.q[2][i]*U.q[2][i]
                  + U.q[3][i]*U.q[3][i]
                )/(rho*rho);
            const double u2New = 2*(H - hNew);
            if (!(u2 > 0) || !(u2New > 0)) break;
            const double scale = rhoNew/rho*std::sqrt(u2New/u2);
            double dq[5];
            dq[0] = rhoNew - rho;
            for (int c = 1; c <= 3; ++c) dq[c] = (scale - 1)*U.q[c][i];
            dq[4] = rhoNew*H - p - U.q[4][i];
            if (transfer)
            {
                // Taken from the diagonal cell B, which shares a face with
                // both A and C (a correction of the flux through that face):
                // conservative; skipped if B would become inadmissible
                for (int c = 0; c < 5; ++c) U.q[c][k.B] -= dq[c];
                if (!U.admissible(k.B, g))
                {
                    for (int c = 0; c < 5; ++c) U.q[c][k.B] += dq[c];
                    break;
                }
            }
            dMass += dq[0]*V;
            dEnergy += dq[4]*V;
            for (int c = 0; c < 5; ++c) U.q[c][i] += dq[c];
            ++n;
        }
    }
    return n;
}


// ************************************************************************* //
