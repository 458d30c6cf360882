/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "semiImplicitStepper.H"
#include "pressureFaceAssembly.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace gasSteppers
{
    defineTypeNameAndDebug(semiImplicitStepper, 0);
    addToRunTimeSelectionTable(gasStepper, semiImplicitStepper, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasSteppers::semiImplicitStepper::semiImplicitStepper
(
    const dictionary& dict,
    eulerOperator& op
)
:
    gasStepper(dict, op),
    tol_(dictionaryChecks::getPositive(dict, "CGtolerance", 1e-10)),
    maxIter_(dictionaryChecks::getLabelAtLeast(dict, "CGmaxIter", 1000, 1)),
    CFL_(dictionaryChecks::getPositive(dict, "CFL", 0.5))
{
    g_ = dictionaryChecks::getBoundedVector
    (
        dict, "gravity", Zero, 1e10, "an acceleration [m/s^2]"
    );
    gravity_ = magSqr(g_) > 0;
    // A step whose relative residual stays above 1e-3 is rejected (below),
    // so a looser tolerance could never give an accepted step
    if (tol_ > 1e-3)
    {
        dictionaryChecks::badEntry
        (
            dict, "CGtolerance", Foam::name(tol_), "a number in (0, 1e-3]"
        );
    }
    Ustar_.resize(mesh_.nLattice());
    unknownOf_.assign(mesh_.nLattice(), -1);
    for (size_t k = 0; k < cells_.size(); ++k)
    {
        unknownOf_[cells_[k]] = label(k);
    }
    p_.assign(cells_.size(), 0.0);
    if (Pstream::parRun())
    {
        // Couplings across processor faces: the unknown next to each slot
        sys_.mesh = &mesh_;
        sys_.slotUnknown.resize(mesh_.nGhostSlots());
        for (label j = 0; j < mesh_.nGhostSlots(); ++j)
        {
            sys_.slotUnknown[j] = unknownOf_[mesh_.slotCell(j)];
        }
    }
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const label nf = mesh_.nFaces(d);
        uStarF_[d].assign(nf, 0.0);
        rhoF_[d].assign(nf, 0.0);
        uF_[d].assign(nf, 0.0);
        pF_[d].assign(nf, 0.0);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::gasSteppers::semiImplicitStepper::stableDeltaT
(
    const gasState& U,
    scalar CFL,
    scalar& speed,
    word& limiter
) const
{
    auto pressure = [&](label i)
    {
        const double rho = U.q[0][i];
        return (gamma_ - 1)*(U.q[4][i] - 0.5*(U.q[1][i]*U.q[1][i]
          + U.q[2][i]*U.q[2][i] + U.q[3][i]*U.q[3][i])/rho);
    };

    // Parallel: the neighbour ranks' cells next to processor faces
    std::vector<double> gU, gOpen;
    if (Pstream::parRun())
    {
        mesh_.exchangeGhosts(U.q, 1, gU);
        if (open_)
        {
            // the open fraction of the cell across each processor face
            std::vector<double> mine(gU.size()/5);
            for (size_t j = 0; j < mine.size(); ++j)
            {
                mine[j] = (*open_)[mesh_.slotCell(label(j))];
            }
            mesh_.exchangeSlots(mine, gOpen);
        }
    }
    auto ghostPressure = [&](label slot)
    {
        const double* q = gU.data() + 5*slot;
        return (gamma_ - 1)
           *(q[4] - 0.5*(q[1]*q[1] + q[2]*q[2] + q[3]*q[3])/q[0]);
    };

    scalar rate = 0;
    scalar rateU = 0;
    speed = 0;
    const auto& cellAt = mesh_.cellAt();
    const label nLat = mesh_.nLattice();
    for (const label i : cells_)
    {
        const double rho = U.q[0][i];
        double ru = 0, rp = 0, u2 = 0;
        for (label d = 0; d < 3; ++d)
        {
            if (!mesh_.active(d)) continue;
            const double ud = U.q[1 + d][i]/rho;
            u2 += ud*ud;
            ru += std::abs(ud)/mesh_.dx(d);

            // Pressure difference across the cell (one-sided at ends)
            const label st = mesh_.stride(d);
            const label lo = i - st, hi = i + st;
            bool hasLo = lo >= 0 && cellAt[lo] >= 0
                && mesh_.lowFaceOf(d)[lo] + 1 == mesh_.lowFaceOf(d)[i];
            bool hasHi = hi < nLat && cellAt[hi] >= 0
                && mesh_.lowFaceOf(d)[i] + 1 == mesh_.lowFaceOf(d)[hi];
            double pLo = hasLo ? pressure(lo) : 0;
            double pHi = hasHi ? pressure(hi) : 0;
            double oLo = (open_ && hasLo) ? (*open_)[lo] : 1;
            double oHi = (open_ && hasHi) ? (*open_)[hi] : 1;
            if (Pstream::parRun() && !(hasLo && hasHi))
            {
                const cartesianMesh::segment& sg =
                    mesh_.segmentOfFace(d, mesh_.lowFaceOf(d)[i]);
                if (!hasLo && i == sg.start && sg.lowGhost >= 0)
                {
                    hasLo = true;
                    pLo = ghostPressure(sg.lowGhost);
                    if (open_) oLo = gOpen[sg.lowGhost];
                }
                if
                (
                    !hasHi && i == sg.start + (sg.length - 1)*st
                 && sg.highGhost >= 0
                )
                {
                    hasHi = true;
                    pHi = ghostPressure(sg.highGhost);
                    if (open_) oHi = gOpen[sg.highGhost];
                }
            }
            double dp = 0;
            if (open_)
            {
                // each face's difference by its smaller open fraction
                const double oi = (*open_)[i];
                const double pi = pressure(i);
                const double dHi = hasHi ? min(oi, oHi)*(pHi - pi) : 0;
                const double dLo = hasLo ? min(oi, oLo)*(pi - pLo) : 0;
                dp = (hasLo && hasHi) ? 0.5*(dHi + dLo) : dHi + dLo;
            }
            else if (hasLo && hasHi) dp = 0.5*(pHi - pLo);
            else if (hasHi) dp = pHi - pressure(i);
            else if (hasLo) dp = pressure(i) - pLo;
            rp += std::abs(dp)/(rho*mesh_.dx(d)*mesh_.dx(d));
        }
        speed = std::max(speed, std::sqrt(u2));
        rateU = std::max(rateU, ru);
        rate = std::max(rate, ru + std::sqrt(rp));
    }
    limiter = rate > 1.0001*rateU ? "|u|+pressure" : "|u|";
    // (a rank whose gas is at rest but for round-off, e.g. denormal
    // velocities ahead of a shock, would overflow CFL/rate)
    return rate > CFL/GREAT ? CFL/rate : GREAT;
}


bool Foam::gasSteppers::semiImplicitStepper::advance
(
    const gasState& U,
    scalar dt,
    gasState& out,
    report& rep
)
{
    // 1. (3.10-3.12) advection, (3.13) rho^{n+1} = rho*
    if (!rungeKutta(U, dt, true, Ustar_, rep))
    {
        return false;
    }

    const scalar V = mesh_.cellVolume();
    const label n = label(cells_.size());
    const PtrList<gasBoundary>& bcs = op_.boundaries();

    auto pressure = [&](const gasState& S, label i)
    {
        const double rho = S.q[0][i];
        return (gamma_ - 1)*(S.q[4][i] - 0.5*(S.q[1][i]*S.q[1][i]
          + S.q[2][i]*S.q[2][i] + S.q[3][i]*S.q[3][i])/rho);
    };

    // Parallel: the neighbour ranks' advected cells at processor faces
    std::vector<double> gS;
    if (Pstream::parRun()) mesh_.exchangeGhosts(Ustar_.q, 1, gS);

    // 2.-3. (3.22) with (3.21): diagonal and source of each cell
    sys_.reset(n);
    for (label k = 0; k < n; ++k)
    {
        const label i = cells_[k];
        const double pn = pressure(U, i);
        const double ps = pressure(Ustar_, i);
        const double a = V/(gamma_*pn*dt*dt);
        sys_.diag[k] = a;
        sys_.source[k] = a*ps;
        p_[k] = ps;
    }

    // (3.21) on the faces
    pressureFaceAssembly faces;
    faces.bodyForce = gravity_;
    faces.assemble
    (
        mesh_, bcs, Ustar_, gS, unknownOf_, dt, g_, sys_,
        rhoF_, uStarF_, uF_
    );

    rep.cgIterations = sys_.solve(p_, tol_, maxIter_, rep.cgResidual);
    if (!std::isfinite(rep.cgResidual) || rep.cgResidual > 1e-3)
    {
        ++rep.explicitFallbacks;
        rep.fallbackReason =
            "the pressure system did not converge (relative residual "
          + Foam::name(rep.cgResidual) + " after "
          + std::to_string(rep.cgIterations) + " CG iterations)";
        return explicitFallback(U, dt, out, rep);
    }

    // Parallel: the neighbour ranks' pressures at processor faces
    std::vector<double> pG;
    if (Pstream::parRun())
    {
        std::vector<double> mine(sys_.slotUnknown.size());
        for (size_t j = 0; j < mine.size(); ++j)
        {
            mine[j] = p_[sys_.slotUnknown[j]];
        }
        mesh_.exchangeSlots(mine, pG);
    }

    // 4. (3.21) face velocities and pressures, then the flux-form updates
    for (int c = 0; c < 5; ++c) out.q[c] = Ustar_.q[c];
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const scalar dx = mesh_.dx(d);
        std::vector<double>& uF = uF_[d];
        std::vector<double>& pF = pF_[d];
        auto faceOf = [&](label f, double pl, double pr)
        {
            uF[f] = uStarF_[d][f] - dt*(pr - pl)/(dx*rhoF_[d][f]);
            pF[f] = 0.5*(pl + pr);
        };
        pressureFaceAssembly::forEachFace
        (
            mesh_, bcs, d,
            [&](label f, label l, label r)
            {
                faceOf(f, p_[unknownOf_[l]], p_[unknownOf_[r]]);
            },
            [&](label fLo, label fHi)
            {
                uF[fHi] = uF[fLo];
                pF[fHi] = pF[fLo];
            },
            // (a boundary face's velocity is its condition's, set by the
            // assembly)
            [&](label f, label i, label, bool)
            {
                pF[f] = p_[unknownOf_[i]];
            },
            // A processor face: the neighbour rank's pressure at its slot
            [&](label f, label slot, label i, bool low)
            {
                if (low) faceOf(f, pG[slot], p_[unknownOf_[i]]);
                else faceOf(f, p_[unknownOf_[i]], pG[slot]);
            }
        );

        // What the pressure carries through the patches: the cells' p at
        // a wall, inlet or outlet face, with the face velocity's work
        addPressureCrossing(d, dt, pF, uF, nullptr);

        const auto& lowFace = mesh_.lowFaceOf(d);
        std::vector<double>& m = out.q[1 + d];
        std::vector<double>& E = out.q[4];
        for (const label i : cells_)
        {
            const label f = lowFace[i];
            m[i] -= dt*(pF[f + 1] - pF[f])/dx;
            E[i] -= dt*(pF[f + 1]*uF[f + 1] - pF[f]*uF[f])/dx;
        }
        if (gravity_)
        {
            // Half of rho_f g and rho_f u_f g of each of the cell's two
            // faces, so that the balance p_r - p_l = rho_f g dx of every
            // face leaves the cells at rest; a boundary face (wall, inlet,
            // outlet: its pressure is the cell's) carries its half itself
            const double gd = g_[d];
            const std::vector<double>& rF = rhoF_[d];
            for (const label i : cells_)
            {
                const label f = lowFace[i];
                const cartesianMesh::segment& sg = mesh_.segmentOfFace(d, f);
                const bool periodic =
                    bcs[sg.lowPatch].kindOf() == gasBoundary::kind::periodic;
                const bool lowEnd = f == sg.faceOffset
                    && !periodic && !(sg.lowGhost >= 0);
                const bool highEnd = f + 1 == sg.faceOffset + sg.length
                    && !periodic && !(sg.highGhost >= 0);
                const double r0 = lowEnd ? 0 : rF[f];
                const bool wrap =
                    periodic && f + 1 == sg.faceOffset + sg.length;
                const double r1 =
                    highEnd ? 0 : (wrap ? rF[sg.faceOffset] : rF[f + 1]);
                m[i] += dt*gd*0.5*(r0 + r1);
                E[i] += dt*gd*0.5*(r0*uF[f] + r1*uF[f + 1]);
            }
        }
    }

    if (Pstream::parRun())
    {
        label badCell = -1;
        for (const label i : cells_)
        {
            if (!out.admissible(i, gamma_))
            {
                badCell = i;
                break;
            }
        }
        // All ranks take the explicit fallback together
        bool ok = badCell < 0;
        reduce(ok, andOp<bool>());
        if (!ok && badCell < 0)
        {
            ++rep.explicitFallbacks;
            rep.fallbackReason = "an inadmissible state on another processor";
            return explicitFallback(U, dt, out, rep);
        }
    }
    for (const label i : cells_)
    {
        if (!out.admissible(i, gamma_))
        {
            // Halving dt does not help here: at a jump of pressure the
            // kinetic energy the pressure step gives a cell and the work it
            // does on it both scale with dt^2, so their ratio does not
            // change.  Take the step with the explicit scheme instead.
            ++rep.explicitFallbacks;
            rep.fallbackReason =
                out.whyInadmissible(i, gamma_) + " in cell "
              + std::to_string(mesh_.cellAt()[i]);
            return explicitFallback(U, dt, out, rep);
        }
    }
    return true;
}


bool Foam::gasSteppers::semiImplicitStepper::explicitFallback
(
    const gasState& U,
    scalar dt,
    gasState& out,
    report& rep
)
{
    // Sub-steps of at most the acoustic CFL step that end exactly at dt,
    // each recomputed from the current state (the waves speed up); what
    // the abandoned step carried through the patches does not count
    clearCrossed();
    for (int c = 0; c < 5; ++c) Ustar_.q[c] = U.q[c];
    scalar left = dt;
    while (true)
    {
        scalar speed = 0;
        scalar rate = acousticRate(Ustar_, speed);
        if (Pstream::parRun()) reduce(rate, maxOp<scalar>());
        const scalar hMax = rate > 0 ? CFL_/rate : left;
        const scalar n = std::max(std::ceil(left/hMax - 1e-9), scalar(1));
        const scalar h = left/n;
        ++rep.explicitSubsteps;
        if (!rungeKutta(Ustar_, h, false, out, rep))
        {
            return false;
        }
        if (n <= 1) return true;
        left -= h;
        std::swap(Ustar_, out);
    }
}


// ************************************************************************* //
