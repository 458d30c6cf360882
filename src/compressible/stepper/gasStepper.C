/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "gasStepper.H"
#include "dictionaryChecks.H"

namespace Foam
{
    defineTypeNameAndDebug(gasStepper, 0);
    defineRunTimeSelectionTable(gasStepper, dictionary);
}

const Foam::Enum<Foam::gasStepper::rkOrder>
Foam::gasStepper::rkOrderNames
({
    { rkOrder::RK2, "RK2" },
    { rkOrder::RK3, "RK3" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasStepper::gasStepper(const dictionary& dict, eulerOperator& op)
:
    op_(op),
    mesh_(op.mesh()),
    gamma_(op.gas().gamma()),
    rk_(dictionaryChecks::getEnum
    (
        dict, "timeIntegration", rkOrderNames, rkOrder::RK3
    ))
{
    const auto& lat = mesh_.latticeOf();
    cells_.assign(lat.begin(), lat.end());
    std::sort(cells_.begin(), cells_.end());
    U1_.resize(mesh_.nLattice());
    U2_.resize(mesh_.nLattice());
    mark_.assign(mesh_.nLattice(), 0);
    fell_.assign(mesh_.nLattice(), 0);
}


Foam::autoPtr<Foam::gasStepper> Foam::gasStepper::New
(
    const dictionary& dict,
    eulerOperator& op
)
{
    word name;
    auto ctor = dictionaryChecks::selectConstructor
    (
        dict, "stepper", *dictionaryConstructorTablePtr_, name
    );
    return autoPtr<gasStepper>(ctor(dict, op));
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

bool Foam::gasStepper::stage
(
    const gasState& U0,
    const gasState& Us,
    scalar a,
    scalar b,
    scalar dt,
    bool advective,
    gasState& out,
    report& rep
)
{
    op_.computeFluxes(Us, advective);

    auto update = [&](label i)
    {
        double r[5];
        op_.rhs(i, r);
        for (int c = 0; c < 5; ++c)
        {
            out.q[c][i] = a*U0.q[c][i] + b*(Us.q[c][i] + dt*r[c]);
        }
    };

    const label fallbackBefore = rep.fallbackCells;
    std::vector<label> bad;
    for (const label i : cells_)
    {
        update(i);
        if (!out.admissible(i, gamma_)) bad.push_back(i);
    }

    // Positivity fallback: first-order fluxes around the offending cells
    auto fallback = [&](std::vector<label>& bad)
    {
        for (label pass = 0; pass < 4 && !bad.empty(); ++pass)
        {
            std::vector<label> touched;
            for (const label i : bad)
            {
                op_.firstOrderFaces(Us, i, advective);
                ++rep.fallbackCells;
                if (!fell_[i])
                {
                    fell_[i] = 1;
                    fellCells_.push_back(i);
                }
                auto touch = [&](label j)
                {
                    if (j >= 0 && j < mesh_.nLattice() && !mark_[j]
                     && mesh_.cellAt()[j] >= 0)
                    {
                        mark_[j] = 1;
                        touched.push_back(j);
                    }
                };
                touch(i);
                for (label d = 0; d < 3; ++d)
                {
                    if (!mesh_.active(d)) continue;
                    touch(i - mesh_.stride(d));
                    touch(i + mesh_.stride(d));
                }
            }
            bad.clear();
            for (const label j : touched)
            {
                mark_[j] = 0;
                update(j);
                if (!out.admissible(j, gamma_)) bad.push_back(j);
            }
        }
    };
    fallback(bad);

    // Parallel: a processor face is one face of the serial lattice.  When
    // the cell on one side fell back, the rank on the other side takes the
    // same first-order flux for that face and updates its cell again (which
    // may fall back in turn), until no rank has news
    label fromNeighbours = 0;
    if (Pstream::parRun())
    {
        const label nSlots = mesh_.nGhostSlots();
        std::vector<double> mine(nSlots), theirs;
        std::vector<char> taken(nSlots, 0);
        for (label round = 0; round < 8; ++round)
        {
            for (label j = 0; j < nSlots; ++j)
            {
                mine[j] = fell_[mesh_.slotCell(j)] ? 1 : 0;
            }
            mesh_.exchangeSlots(mine, theirs);
            bool news = false;
            for (label j = 0; j < nSlots; ++j)
            {
                const label c = mesh_.slotCell(j);
                if (theirs[j] > 0 && !taken[j] && !fell_[c])
                {
                    taken[j] = 1;
                    op_.firstOrderSlotFace(Us, j, advective);
                    ++fromNeighbours;
                    update(c);
                    if (!out.admissible(c, gamma_)) bad.push_back(c);
                    news = true;
                }
            }
            fallback(bad);
            reduce(news, orOp<bool>());
            if (!news) break;
        }
    }
    for (const label i : fellCells_) fell_[i] = 0;
    fellCells_.clear();

    // A replaced face of a periodic line's end cell also belongs to the cell
    // at its other end: refresh every update once, so no cell keeps a stale
    // flux and the stage stays conservative
    if ((fallbackBefore != rep.fallbackCells || fromNeighbours) && bad.empty())
    {
        for (const label i : cells_)
        {
            update(i);
            if (!out.admissible(i, gamma_)) bad.push_back(i);
        }
    }

    if (Pstream::parRun())
    {
        // All ranks agree whether the stage failed, so all retry together
        bool ok = bad.empty();
        reduce(ok, andOp<bool>());
        if (!ok && bad.empty())
        {
            rep.failure = "a state failed on another processor";
            return false;
        }
    }
    if (!bad.empty())
    {
        rep.failedCell = bad.front();
        rep.failure =
            (advective ? "after the advection: " : "")
          + out.whyInadmissible(bad.front(), gamma_);
        return false;
    }
    return true;
}


bool Foam::gasStepper::rungeKutta
(
    const gasState& U,
    scalar dt,
    bool advective,
    gasState& out,
    report& rep
)
{
    // What crossed the patches combines as the states do, from none at U:
    // acc = b (acc + dt B(Us)) per stage (RK3: dt (B0 + B1 + 4 B2)/6)
    double acc[5] = {0, 0, 0, 0, 0};
    auto crossing = [&](scalar b)
    {
        double B[5];
        op_.boundaryFlux(B);
        for (int c = 0; c < 5; ++c) acc[c] = b*(acc[c] + dt*B[c]);
        return true;
    };
    bool ok;
    if (rk_ == rkOrder::RK2)
    {
        // TVD RK2 (Heun)
        ok =
            stage(U, U, 0, 1, dt, advective, U1_, rep) && crossing(1)
         && stage(U, U1_, 0.5, 0.5, dt, advective, out, rep) && crossing(0.5);
    }
    else
    {
        // TVD RK3 (Shu and Osher)
        ok =
            stage(U, U, 0, 1, dt, advective, U1_, rep) && crossing(1)
         && stage(U, U1_, 0.75, 0.25, dt, advective, U2_, rep)
         && crossing(0.25)
         && stage(U, U2_, 1.0/3.0, 2.0/3.0, dt, advective, out, rep)
         && crossing(2.0/3.0);
    }
    for (int c = 0; c < 5; ++c) crossed_[c] += acc[c];
    return ok;
}


void Foam::gasStepper::addPressureCrossing
(
    label d,
    scalar dt,
    const std::vector<double>& pF,
    const std::vector<double>& uF,
    const std::vector<double>* open
)
{
    const PtrList<gasBoundary>& bcs = op_.boundaries();
    const scalar A = mesh_.cellVolume()/mesh_.dx(d);
    for (const auto& s : mesh_.segments(d))
    {
        if (bcs[s.lowPatch].kindOf() == gasBoundary::kind::periodic)
        {
            continue;
        }
        double pIn = 0, pOut = 0, wIn = 0, wOut = 0;
        if (s.lowGhost < 0)
        {
            const label f = s.faceOffset;
            pIn = pF[f];
            wIn = pF[f]*(open ? (*open)[f] : 1.0)*uF[f];
        }
        if (s.highGhost < 0)
        {
            const label f = s.faceOffset + s.length;
            pOut = pF[f];
            wOut = pF[f]*(open ? (*open)[f] : 1.0)*uF[f];
        }
        crossed_[1 + d] += dt*A*(pOut - pIn);
        crossed_[4] += dt*A*(wOut - wIn);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::gasStepper::acousticRate
(
    const gasState& U,
    scalar& maxSpeed
) const
{
    scalar rate = 0;
    maxSpeed = 0;
    for (const label i : cells_)
    {
        const double rho = U.q[0][i];
        const double u[3] =
            {U.q[1][i]/rho, U.q[2][i]/rho, U.q[3][i]/rho};
        const double p = (gamma_ - 1)
           *(U.q[4][i] - 0.5*rho*(u[0]*u[0] + u[1]*u[1] + u[2]*u[2]));
        const double c = std::sqrt(std::abs(gamma_*p/rho));
        double r = 0;
        for (label d = 0; d < 3; ++d)
        {
            if (mesh_.active(d)) r += (std::abs(u[d]) + c)/mesh_.dx(d);
        }
        rate = std::max(rate, r);
        maxSpeed = std::max
        (
            maxSpeed,
            std::sqrt(u[0]*u[0] + u[1]*u[1] + u[2]*u[2]) + c
        );
    }
    return rate;
}


// ************************************************************************* //
