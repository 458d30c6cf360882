/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "csmpmStepper.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// (3.21)-(3.24) discretised, reduced to (3.37), solved; (3.36) for the
// solid's nodes, local gradients (3.21) for the gas
bool Foam::csmpmStepper::pressureStep
(
    const gasState& U,
    scalar dt,
    gasState& out,
    report& rep
)
{
    const scalar V = mesh_.cellVolume();
    const label n = label(cells_.size());
    const PtrList<gasBoundary>& bcs = op_.boundaries();
    mpmGrid& grid = solver_.grid();
    List<vector>& vs = grid.newVelocity;

    auto pressure = [&](const gasState& S, label i)
    {
        const double rho = S.q[0][i];
        return (gamma_ - 1)*(S.q[4][i] - 0.5*(S.q[1][i]*S.q[1][i]
          + S.q[2][i]*S.q[2][i] + S.q[3][i]*S.q[3][i])/rho);
    };

    // The faces the solid couples to: R > 0 and some node of the face with
    // solid mass; the face's B-spline weights renormalised over those
    // nodes, so that the solid's force and the gas's add up to the face's
    // pressure jump exactly (momentum conserved to round-off)
    const scalar tiny = VSMALL;
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const std::vector<double>& R = lattice_.R(d);
        Reff_[d] = R;
        const std::vector<label>& nodes = lattice_.nodes(d);
        const std::vector<double>& w = lattice_.weights(d);
        wNorm_[d].resize(w.size());
        for (const auto& fc : lattice_.faces(d))
        {
            if (R[fc.f] <= 0) continue;
            double ws = 0;
            for (label e = fc.node0; e < fc.node0 + fc.nNodes; ++e)
            {
                if (grid.mass[nodes[e]] > tiny) ws += w[e];
            }
            if (ws <= 0)
            {
                Reff_[d][fc.f] = 0;
                continue;
            }
            for (label e = fc.node0; e < fc.node0 + fc.nNodes; ++e)
            {
                wNorm_[d][e] = grid.mass[nodes[e]] > tiny ? w[e]/ws : 0;
            }
        }
        // Boundary and periodic faces: both phases take the condition
        for (const auto& s : mesh_.segments(d))
        {
            Reff_[d][s.faceOffset] = 0;
            Reff_[d][s.faceOffset + s.length] = 0;
        }
        openEff_[d].resize(R.size());
        for (size_t f = 0; f < R.size(); ++f) openEff_[d][f] = 1 - Reff_[d][f];
    }

    // (3.22), (3.24): compressibilities mixed by the solid fraction, and
    // the intermediate pressure that goes with them
    pressureSystem& gsys = sys_.gas;
    gsys.reset(n);
    for (label k = 0; k < n; ++k)
    {
        const label i = cells_[k];
        const double pGas = pressure(Ustar_, i);
        const double kGas = 1.0/(gamma_*pressure(U, i));
        const double phi = lattice_.phi(i);
        double kappa = kGas, ps = pGas;
        if (phi > 0)
        {
            const double kSol = 1.0/lattice_.Kg(i);
            kappa = (1 - phi)*kGas + phi*kSol;
            ps = ((1 - phi)*kGas*pGas + phi*kSol*lattice_.pg(i))/kappa;
        }
        const double a = V*kappa/(dt*dt);
        gsys.diag[k] = a;
        gsys.source[k] = a*ps;
        p_[k] = ps;
    }

    // (3.21) on the passable share of each face; boundary faces carry
    // their velocity for both phases
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const scalar A = V/mesh_.dx(d);
        const scalar dx = mesh_.dx(d);
        const label st = mesh_.stride(d);
        const std::vector<double>& open = openEff_[d];
        for (const auto& s : mesh_.segments(d))
        {
            const bool periodic =
                bcs[s.lowPatch].kindOf() == gasBoundary::kind::periodic;
            auto coupleCells = [&](label f, label l, label r)
            {
                const double rhoF = 0.5*(Ustar_.q[0][l] + Ustar_.q[0][r]);
                const double uS = 0.5
                   *(
                        Ustar_.q[1 + d][l]/Ustar_.q[0][l]
                      + Ustar_.q[1 + d][r]/Ustar_.q[0][r]
                    );
                rhoF_[d][f] = rhoF;
                uStarF_[d][f] = uS;
                const double a = open[f];
                if (a <= 0) return;
                const label kl = unknownOf_[l], kr = unknownOf_[r];
                gsys.couple(kl, kr, a*A/(rhoF*dx));
                gsys.source[kl] -= a*A*uS/dt;
                gsys.source[kr] += a*A*uS/dt;
            };
            for (label m = 1; m < s.length; ++m)
            {
                coupleCells
                (
                    s.faceOffset + m, s.start + (m - 1)*st, s.start + m*st
                );
            }
            const label first = s.start;
            const label last = s.start + (s.length - 1)*st;
            if (periodic)
            {
                coupleCells(s.faceOffset, last, first);
            }
            else
            {
                double q[5];
                for (int c = 0; c < 5; ++c) q[c] = Ustar_.q[c][first];
                const double uLo = bcs[s.lowPatch].faceVelocity(q, d);
                for (int c = 0; c < 5; ++c) q[c] = Ustar_.q[c][last];
                const double uHi = bcs[s.highPatch].faceVelocity(q, d);
                uF_[d][s.faceOffset] = uLo;
                uF_[d][s.faceOffset + s.length] = uHi;
                usF_[d][s.faceOffset] = uLo;
                usF_[d][s.faceOffset + s.length] = uHi;
                gsys.source[unknownOf_[first]] += A*uLo/dt;
                gsys.source[unknownOf_[last]] -= A*uHi/dt;
            }
        }
    }

    // The solid's part: T = W^T G over the faces the solid blocks
    sys_.beginSolid(grid.mass.size());
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const scalar A = V/mesh_.dx(d);
        const std::vector<double>& R = Reff_[d];
        const std::vector<label>& nodes = lattice_.nodes(d);
        const std::vector<double>& w = wNorm_[d];
        for (const auto& fc : lattice_.faces(d))
        {
            const double Rf = R[fc.f];
            if (Rf <= 0) continue;
            const label kl = unknownOf_[fc.l], kr = unknownOf_[fc.r];
            for (label e = fc.node0; e < fc.node0 + fc.nNodes; ++e)
            {
                const label i = nodes[e];
                if (!(grid.mass[i] > tiny)) continue;
                sys_.addFaceNode(i, d, kl, kr, A*Rf*w[e]);
            }
        }
    }
    massScaled_.setSize(grid.mass.size());
    {
        const scalar sc = lattice_.scale();
        for (label k = 0; k < sys_.nRows(); ++k)
        {
            const label i = sys_.rowNode(k);
            massScaled_[i] = sc*grid.mass[i];
        }
    }
    sys_.endSolid(massScaled_);
    sys_.addSolidSource(vs, dt);

    rep.cgIterations = sys_.solve(p_, tol_, maxIter_, rep.cgResidual);
    if (!std::isfinite(rep.cgResidual) || rep.cgResidual > 1e-3)
    {
        rep.failure =
            "the coupled pressure system did not converge (relative"
            " residual " + std::to_string(rep.cgResidual) + " after "
          + std::to_string(rep.cgIterations) + " CG iterations)";
        return false;
    }

    // (3.36): v = v* - dt M^-1 T p on the solid's nodes
    sys_.applyT(p_, Tp_);
    for (label k = 0; k < sys_.nRows(); ++k)
    {
        const label i = sys_.rowNode(k);
        vs[i][sys_.rowDir(k)] -= dt*Tp_[k]/massScaled_[i];
    }

    // (3.21) gas face velocities; the solid's velocity at each face
    for (int c = 0; c < 5; ++c) out.q[c] = Ustar_.q[c];
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const scalar dx = mesh_.dx(d);
        const label st = mesh_.stride(d);
        const std::vector<double>& open = openEff_[d];
        std::vector<double>& uF = uF_[d];
        std::vector<double>& pF = pF_[d];
        std::vector<double>& usF = usF_[d];

        // Momentum impulse of the passable share of each face
        std::vector<double>& J = uStarF_[d];    // reused after uF is set
        for (const auto& s : mesh_.segments(d))
        {
            const bool periodic =
                bcs[s.lowPatch].kindOf() == gasBoundary::kind::periodic;
            auto face = [&](label f, label l, label r)
            {
                const double pl = p_[unknownOf_[l]], pr = p_[unknownOf_[r]];
                uF[f] = uStarF_[d][f] - dt*(pr - pl)/(dx*rhoF_[d][f]);
                pF[f] = 0.5*(pl + pr);
                usF[f] = 0;
                J[f] = open[f]*(pl - pr);
            };
            for (label m = 1; m < s.length; ++m)
            {
                face(s.faceOffset + m, s.start + (m-1)*st, s.start + m*st);
            }
            const label first = s.start;
            const label last = s.start + (s.length - 1)*st;
            if (periodic)
            {
                face(s.faceOffset, last, first);
                uF[s.faceOffset + s.length] = uF[s.faceOffset];
                pF[s.faceOffset + s.length] = pF[s.faceOffset];
                usF[s.faceOffset + s.length] = 0;
                J[s.faceOffset + s.length] = J[s.faceOffset];
            }
            else
            {
                pF[s.faceOffset] = p_[unknownOf_[first]];
                pF[s.faceOffset + s.length] = p_[unknownOf_[last]];
                J[s.faceOffset] = 0;
                J[s.faceOffset + s.length] = 0;
            }
        }
        const std::vector<label>& nodes = lattice_.nodes(d);
        const std::vector<double>& w = wNorm_[d];
        const std::vector<double>& R = Reff_[d];
        for (const auto& fc : lattice_.faces(d))
        {
            if (R[fc.f] <= 0) continue;
            double u = 0;
            for (label e = fc.node0; e < fc.node0 + fc.nNodes; ++e)
            {
                u += w[e]*vs[nodes[e]][d];
            }
            usF[fc.f] = u;
        }

        const auto& lowFace = mesh_.lowFaceOf(d);
        std::vector<double>& m = out.q[1 + d];
        std::vector<double>& E = out.q[4];
        for (const label i : cells_)
        {
            const label f = lowFace[i];
            // Gas momentum from the passable share (the rest pushes the
            // solid); equal to -dt (p_{f+1} - p_f)/dx where nothing blocks
            m[i] += 0.5*dt*(J[f] + J[f + 1])/dx;
            const double a0 = open[f], a1 = open[f + 1];
            const double F0 = pF[f]*(a0*uF[f] + (1 - a0)*usF[f]);
            const double F1 = pF[f + 1]*(a1*uF[f + 1] + (1 - a1)*usF[f + 1]);
            E[i] -= dt*(F1 - F0)/dx;
        }
    }

    for (const label i : cells_)
    {
        if (!out.admissible(i, gamma_))
        {
            rep.failedCell = i;
            rep.failure = out.whyInadmissible(i, gamma_)
              + " after the coupled pressure step";
            return false;
        }
    }
    return true;
}


// ************************************************************************* //
