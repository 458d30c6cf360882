/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "csmpmStepper.H"
#include "pressureFaceAssembly.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// The faces the solid couples to, before the advection
void Foam::csmpmStepper::couplingFaces()
{
    const mpmGrid& grid = solver_.grid();
    // The faces the solid couples to: R > 0 and some node of the face with
    // solid mass; the face's B-spline weights renormalised over those
    // nodes, so that the solid's force and the gas's add up to the face's
    // pressure jump exactly (momentum conserved to round-off)
    // A node the solid barely reaches (the tail of the kernel) would bring
    // 1/m_i of many decades into the system: nodes below a thousandth of
    // the smallest particle's mass take no part
    // Only the faces and cells the deposit touched are visited; those of
    // the previous step are reset first
    const scalar tiny = nodeMassMin_;
    // (parallel: every copy's mass is the ranks' common one)
    const List<scalar>& mass = par_.valid() ? massAll_ : grid.mass;
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const label nf = mesh_.nFaces(d);
        if (label(Reff_[d].size()) != nf)
        {
            Reff_[d].assign(nf, 0.0);
            openEff_[d].assign(nf, 1.0);
            wNorm_[d].assign(lattice_.weights(d).size(), 0.0);
        }
        for (const label slot : coupledFaces_[d])
        {
            const label f = lattice_.faces(d)[slot].f;
            Reff_[d][f] = 0;
            openEff_[d][f] = 1;
        }
        coupledFaces_[d].clear();

        const std::vector<double>& R = lattice_.R(d);
        const std::vector<label>& nodes = lattice_.nodes(d);
        const std::vector<double>& w = lattice_.weights(d);
        const auto& faces = lattice_.faces(d);
        for (const label f : lattice_.touchedFaces(d))
        {
            // Boundary and periodic faces: both phases take the condition
            const label slot = lattice_.faceSlot(d, f);
            if (slot < 0 || R[f] <= 0) continue;
            const solidLattice::face& fc = faces[slot];
            double ws = 0;
            for (label e = fc.node0; e < fc.node0 + fc.nNodes; ++e)
            {
                if (mass[nodes[e]] > tiny) ws += w[e];
            }
            if (ws <= 0) continue;
            for (label e = fc.node0; e < fc.node0 + fc.nNodes; ++e)
            {
                wNorm_[d][e] = mass[nodes[e]] > tiny ? w[e]/ws : 0;
            }
            Reff_[d][f] = R[f];
            openEff_[d][f] = 1 - R[f];
            coupledFaces_[d].push_back(slot);
        }
    }
    setSolidFractions();
}


// (3.21)-(3.24) discretised, reduced to (3.37), solved; (3.36) for the
// solid's nodes, local gradients (3.21) for the gas
// Steps 4-5 of 3.2.2 on the lattice: assemble (3.37), solve it, project
// the solid (3.36) and the gas (3.21), the solid's work on the gas, repair
bool Foam::csmpmStepper::pressureStep
(
    const gasState& U,
    scalar dt,
    gasState& out,
    report& rep
)
{
    assemblePressure(U, dt);
    if (!solvePressure(rep)) return false;
    projectSolid(dt);
    projectGas(dt, out);
    exchangeWork(out);
    return repairAfterPressure(out, rep);
}


// (3.37): the cells' compressibilities (3.22), (3.24), the gas's faces
// (3.21), the solid's block T = W^T G and its divergence at v*
void Foam::csmpmStepper::assemblePressure(const gasState& U, scalar dt)
{
    const scalar V = mesh_.cellVolume();
    const label n = label(cells_.size());
    const PtrList<gasBoundary>& bcs = op_.boundaries();
    mpmGrid& grid = solver_.grid();
    List<vector>& vs = grid.newVelocity;
    const bool par = par_.valid();
    const List<scalar>& mass = par ? massAll_ : grid.mass;

    // Parallel: the neighbour ranks' advected cells at processor faces
    std::vector<double> gS;
    if (par) mesh_.exchangeGhosts(Ustar_.q, 1, gS);

    auto pressure = [&](const gasState& S, label i)
    {
        const double rho = S.q[0][i];
        return (gamma_ - 1)*(S.q[4][i] - 0.5*(S.q[1][i]*S.q[1][i]
          + S.q[2][i]*S.q[2][i] + S.q[3][i]*S.q[3][i])/rho);
    };

    // (3.22), (3.24): compressibilities mixed by the solid fraction, and
    // the intermediate pressure that goes with them
    pressureSystem& gsys = sys_.gas;
    gsys.reset(n);
    for (label k = 0; k < n; ++k)
    {
        const label i = cells_[k];
        // The gas of a cell the solid partly covers fills the open
        // volume (1 - phi) V: its pressure is the EOS of that volume
        const double phi = lattice_.phi(i);
        const double open = max(1 - phi, gasVolumeMin_);
        const double pGas = pressure(Ustar_, i)/open;
        const double kGas = open/(gamma_*pressure(U, i));
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

    // (3.21) on the passable share of each face, the gas's density its
    // content over the open volume; boundary faces carry their velocity
    // for both phases.  (Gravity: the face's u* takes dt g, as in the gas
    // stepper, so a face in hydrostatic balance stays at rest; B2B1: the
    // gas's couplings are gasB2B1Operator's)
    const bool b2b1 = gasB2B1_.valid();
    pressureFaceAssembly faces;
    faces.faceShare = openEff_;
    faces.cellSolid = &phiCell_;
    faces.slotSolid = &lattice_.phiSlots();
    faces.openMin = gasVolumeMin_;
    faces.gasCouplings = !b2b1;
    faces.bodyForce = true;
    faces.alsoBoundaryVelocity = usF_;
    faces.assemble
    (
        mesh_, bcs, Ustar_, gS, unknownOf_, dt, g_, gsys,
        rhoF_, uStarF_, uF_
    );

    // gasPressureOrder B2B1: the gas's velocities on the vertices (3.32),
    // eliminated (3.35), in place of the face couplings above (the
    // boundary faces' fluxes stay)
    if (b2b1)
    {
        for (const label i : cells_)
        {
            openLat_[i] = max(1 - phiCell_[i], gasVolumeMin_);
        }
        gasB2B1_->setStep(Ustar_.q, openLat_, dt, g_, gsys.source, gsys.diag);
        gsys.blocks.push_back(gasB2B1_.get());
    }

    // The solid's part: T = W^T G over the faces the solid blocks
    const scalar tiny = nodeMassMin_;
    sys_.beginSolid(grid.mass.size());
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const scalar A = V/mesh_.dx(d);
        const std::vector<double>& R = Reff_[d];
        const std::vector<label>& nodes = lattice_.nodes(d);
        const std::vector<double>& w = wNorm_[d];
        for (const label slot : coupledFaces_[d])
        {
            const solidLattice::face& fc = lattice_.faces(d)[slot];
            const double Rf = R[fc.f];
            if (Rf <= 0) continue;
            // (a processor face: the neighbour rank adds its cell's column)
            const label kl = fc.l >= 0 ? unknownOf_[fc.l] : -1;
            const label kr = fc.r >= 0 ? unknownOf_[fc.r] : -1;
            for (label e = fc.node0; e < fc.node0 + fc.nNodes; ++e)
            {
                const label i = nodes[e];
                if (!(mass[i] > tiny)) continue;
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
            massScaled_[i] = sc*mass[i];
        }
    }
    sys_.endSolid(massScaled_);
    if (par)
    {
        // v* at every copy of a node (a copy no particle of its rank
        // touches holds zero; the others hold the same sum)
        vsAll_ = vs;
        par_->combineShared
        (
            vsAll_,
            [](const vector& a, const vector& b)
            {
                return magSqr(a) > 0 ? a : b;
            },
            nullptr
        );
    }
    sys_.addSolidSource(par ? vsAll_ : vs, dt);
    // The solid's block, appended to the gas's system
    gsys.blocks.push_back(&sys_);
}


bool Foam::csmpmStepper::solvePressure(report& rep)
{
    rep.cgIterations = sys_.gas.solve(p_, tol_, maxIter_, rep.cgResidual);
    if (!std::isfinite(rep.cgResidual) || rep.cgResidual > 1e-3)
    {
        rep.failure =
            "the coupled pressure system did not converge (relative"
            " residual " + std::to_string(rep.cgResidual) + " after "
          + std::to_string(rep.cgIterations) + " CG iterations)";
        return false;
    }
    return true;
}


// (3.36): the solid's nodes by the pressure (or, localGradient, the
// ablation of Fig. 3.3)
void Foam::csmpmStepper::projectSolid(scalar dt)
{
    mpmGrid& grid = solver_.grid();
    List<vector>& vs = grid.newVelocity;
    const bool par = par_.valid();
    const List<scalar>& mass = par ? massAll_ : grid.mass;
    const scalar tiny = nodeMassMin_;

    if (!localGradient_)
    {
        // (3.36): v = v* - dt M^-1 T p on the solid's nodes
        sys_.applyT(p_, Tp_);
        if (!par)
        {
            for (label k = 0; k < sys_.nRows(); ++k)
            {
                const label i = sys_.rowNode(k);
                vs[i][sys_.rowDir(k)] -= dt*Tp_[k]/massScaled_[i];
            }
        }
        else
        {
            // Every copy of a node takes the update, also a copy whose
            // rank holds no face of it (its particles still read it):
            // T p summed over the ranks is zero off the rows
            const List<vector>& Tp = sys_.rowsSummed();
            const scalar sc = lattice_.scale();
            forAll(vsAll_, i)
            {
                if (!(mass[i] > tiny)) continue;
                for (label d = 0; d < 3; ++d)
                {
                    if (Tp[i][d] == 0) continue;
                    const double dv = dt*Tp[i][d]/(sc*mass[i]);
                    vsAll_[i][d] -= dv;
                    if (grid.isActive[i]) vs[i][d] -= dv;
                }
            }
        }
    }
    else
    {
        // The ablation of Fig. 3.3 (right): each node by the local
        // pressure gradient, v -= dt grad p/rho_s, the gradient the mean
        // of the differences across the node of the cells around it, rho_s
        // the node's mass over its P2G volume
        const kernelWeights& kw = solver_.weights();
        if (nodeVolume_.size() != grid.mass.size())
        {
            nodeVolume_.setSize(grid.mass.size(), Zero);
        }
        for (const label i : grid.active) nodeVolume_[i] = 0;
        forAll(P_.x, p)
        {
            for (label j = kw.start[p]; j < kw.start[p + 1]; ++j)
            {
                nodeVolume_[kw.vertex[j]] += kw.w[j]*P_.V[p];
            }
        }
        const List<vector>& xv = view_.vertices();
        const auto& cellAt = mesh_.cellAt();
        for (label k = 0; k < sys_.nRows(); ++k)
        {
            const label i = sys_.rowNode(k);
            const label d = sys_.rowDir(k);
            label c[3] = {0, 0, 0};
            for (label e = 0; e < 3; ++e)
            {
                if (!mesh_.active(e)) continue;
                c[e] = label(std::lround
                (
                    (xv[i][e] - mesh_.origin()[e])/mesh_.dx(e)
                ));
            }
            double g = 0;
            label nPairs = 0;
            for (label a = 0; a < 2; ++a)
            for (label b = 0; b < 2; ++b)
            {
                label lo[3], hi[3];
                label ab[2] = {a, b}, q = 0;
                bool ok = true;
                for (label e = 0; e < 3; ++e)
                {
                    if (!mesh_.active(e)) { lo[e] = hi[e] = 0; continue; }
                    if (e == d) { lo[e] = c[e] - 1; hi[e] = c[e]; continue; }
                    lo[e] = hi[e] = c[e] - 1 + (q < 2 ? ab[q++] : 0);
                }
                if (mesh_.nDims() < 3 && b == 1) continue;
                if (mesh_.nDims() < 2 && a == 1) continue;
                for (label e = 0; e < 3; ++e)
                {
                    ok = ok && lo[e] >= 0 && hi[e] < mesh_.n(e);
                }
                if (!ok) continue;
                const label il = lo[0] + mesh_.n(0)*(lo[1] + mesh_.n(1)*lo[2]);
                const label ih = hi[0] + mesh_.n(0)*(hi[1] + mesh_.n(1)*hi[2]);
                if (cellAt[il] < 0 || cellAt[ih] < 0) continue;
                g += p_[unknownOf_[ih]] - p_[unknownOf_[il]];
                ++nPairs;
            }
            if (!nPairs || !(nodeVolume_[i] > 0)) continue;
            const double rho = grid.mass[i]/nodeVolume_[i];
            vs[i][d] -= dt*(g/nPairs)/(mesh_.dx(d)*rho);
        }
    }
}


// (3.21): the gas's face velocities and the flux-form updates of its
// momentum and energy on the passable shares; the solid's face velocities
// and the volume it sweeps per cell (swept_)
void Foam::csmpmStepper::projectGas(scalar dt, gasState& out)
{
    const PtrList<gasBoundary>& bcs = op_.boundaries();
    mpmGrid& grid = solver_.grid();
    List<vector>& vs = grid.newVelocity;
    const bool par = par_.valid();
    auto openRemote = [&](label slot)
    {
        return max(1 - lattice_.phiRemote(slot), gasVolumeMin_);
    };

    // Parallel: the neighbour ranks' pressures at processor faces
    std::vector<double> pG;
    if (par)
    {
        std::vector<double> mine(sys_.gas.slotUnknown.size());
        for (size_t j = 0; j < mine.size(); ++j)
        {
            mine[j] = p_[sys_.gas.slotUnknown[j]];
        }
        mesh_.exchangeSlots(mine, pG);
    }

    // (3.21) gas face velocities; the solid's velocity at each face
    for (int c = 0; c < 5; ++c) out.q[c] = Ustar_.q[c];
    swept_.resize(out.q[0].size());
    for (const label i : cells_) swept_[i] = 0;
    for (label d = 0; d < 3; ++d)
    {
        if (!mesh_.active(d)) continue;
        const scalar dx = mesh_.dx(d);
        const std::vector<double>& open = openEff_[d];
        std::vector<double>& uF = uF_[d];
        std::vector<double>& pF = pF_[d];
        std::vector<double>& usF = usF_[d];

        // Momentum impulse of the passable share of each face
        std::vector<double>& J = uStarF_[d];    // reused after uF is set
        shareL_.resize(J.size());
        // A face between cells of open shares ol, orr at pressures pl, pr
        auto faceOf = [&](label f, double pl, double pr, double ol, double orr)
        {
            uF[f] = uStarF_[d][f] - dt*(pr - pl)/(dx*rhoF_[d][f]);
            pF[f] = 0.5*(pl + pr);
            usF[f] = 0;
            J[f] = open[f]*(pl - pr + rhoF_[d][f]*g_[d]*dx);
            // Shared by the two cells as their gas contents are (a cell
            // the solid covers holds little gas and gets little)
            shareL_[f] = ol/(ol + orr);
        };
        auto openCell = [&](label i)
        {
            return max(1 - phiCell_[i], gasVolumeMin_);
        };
        pressureFaceAssembly::forEachFace
        (
            mesh_, bcs, d,
            [&](label f, label l, label r)
            {
                faceOf
                (
                    f, p_[unknownOf_[l]], p_[unknownOf_[r]],
                    openCell(l), openCell(r)
                );
            },
            [&](label fLo, label fHi)
            {
                uF[fHi] = uF[fLo];
                pF[fHi] = pF[fLo];
                usF[fHi] = 0;
                J[fHi] = J[fLo];
                shareL_[fHi] = shareL_[fLo];
            },
            // A boundary face: the cell's pressure, no impulse
            [&](label f, label i, label, bool)
            {
                pF[f] = p_[unknownOf_[i]];
                J[f] = 0;
            },
            // A processor face as an interior one, the neighbour rank's
            // cell from its slot
            [&](label f, label slot, label i, bool low)
            {
                if (low)
                {
                    faceOf
                    (
                        f, pG[slot], p_[unknownOf_[i]],
                        openRemote(slot), openCell(i)
                    );
                }
                else
                {
                    faceOf
                    (
                        f, p_[unknownOf_[i]], pG[slot],
                        openCell(i), openRemote(slot)
                    );
                }
            }
        );
        // What the pressure carries through the patches: the interior
        // impulses J sum to p_first - p_last per line (less the solid's
        // share), the boundary faces' work is the energy flux below
        addPressureCrossing(d, dt, pF, uF, &open);

        const std::vector<label>& nodes = lattice_.nodes(d);
        const std::vector<double>& w = wNorm_[d];
        const std::vector<double>& R = Reff_[d];
        for (const label slot : coupledFaces_[d])
        {
            const solidLattice::face& fc = lattice_.faces(d)[slot];
            if (R[fc.f] <= 0) continue;
            const List<vector>& v = par ? vsAll_ : vs;
            double u = 0;
            for (label e = fc.node0; e < fc.node0 + fc.nNodes; ++e)
            {
                u += w[e]*v[nodes[e]][d];
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
            m[i] += dt*(J[f]*(1 - shareL_[f]) + J[f + 1]*shareL_[f + 1])/dx;
            const double a0 = open[f], a1 = open[f + 1];
            // The gas's own work on the passable shares (a flux); the
            // solid volume the faces' reflective shares bring in, for the
            // solid's work on the gas of this cell (below)
            const double F0 = pF[f]*a0*uF[f];
            const double F1 = pF[f + 1]*a1*uF[f + 1];
            E[i] -= dt*(F1 - F0)/dx;
            swept_[i] += dt*((1 - a0)*usF[f] - (1 - a1)*usF[f + 1])/dx;
            if (gravity_)
            {
                // The work of gravity on the face's passable share, split
                // as the momentum is
                E[i] += dt*g_[d]
                   *(
                        a0*rhoF_[d][f]*uF[f]*(1 - shareL_[f])
                      + a1*rhoF_[d][f + 1]*uF[f + 1]*shareL_[f + 1]
                    );
            }
        }
    }
}


void Foam::csmpmStepper::exchangeWork(gasState& out) const
{
    // The solid's work on the gas of each cell: the cell's pressure times
    // the volume the solid brings in (the pressure's work on the solid's
    // nodes in (3.36) at their new velocities, turned round; none where
    // the solid crosses a cell rigidly).  Where the solid leaves a cell
    // the gas expands into the volume it frees and pays the same work,
    // p dV with the shared pressure, where that pressure is the gas's
    // (at most its own, (gamma - 1) e_int/open) and the work at most half
    // its internal energy; else (a cell the solid mostly covers, whose
    // shared pressure is the solid's ghost pressure: p dV drained the
    // cells a bending post uncovers in cylindersMach3 to p = 0) the
    // isentropic change of its own internal energy over the open volume's
    // growth.  The isentropic form everywhere gave the gas less to pay
    // than the solid received once the gas's step is long (solidSubsteps:
    // the light bullet of bullet2D gained 1.1 % more kinetic energy than
    // the gas lost; with p dV the gas's loss is 1.0055 times the gain)
    {
        std::vector<double>& E = out.q[4];
        for (const label i : cells_)
        {
            const double W = swept_[i];
            if (W == 0) continue;
            const double p = p_[unknownOf_[i]];
            if (W > 0)
            {
                E[i] += p*W;
            }
            else
            {
                // The gas's own internal energy (in a mostly covered cell
                // far less than the shared pressure's p (1 - phi)/(gamma-1))
                const double eInt = E[i] - 0.5*
                (
                    sqr(out.q[1][i]) + sqr(out.q[2][i]) + sqr(out.q[3][i])
                )/out.q[0][i];
                if (eInt > 0)
                {
                    const double open = max(1 - lattice_.phi(i), gasVolumeMin_);
                    const double pGas = (gamma_ - 1)*eInt/open;
                    if (p <= pGas && p*W >= -0.5*eInt)
                    {
                        E[i] += p*W;
                    }
                    else
                    {
                        E[i] += eInt*(std::pow(1 - W/open, 1 - gamma_) - 1);
                    }
                }
            }
        }
    }
}


// Covered cells merged, cells next to the solid repaired, then every cell
// admissible or the step fails naming one
bool Foam::csmpmStepper::repairAfterPressure(gasState& out, report& rep)
{
    const bool par = par_.valid();
    if (par)
    {
        lastRepaired_ = mergeAndRepairParallel(out);
    }
    else
    {
        mergeCoveredCells(out);
        lastRepaired_ = repairNearSolid(out);
    }
    // A pooled pair can still be inadmissible where a tearing film leaves
    // near-vacuum on both sides of a face: pool again, the pair with its
    // fullest neighbour, a few times (each pass conservative)
    for (label pass = 0; pass < 4; ++pass)
    {
        label r = repairAnywhere(out);
        if (par) reduce(r, maxOp<label>());
        lastRepaired_ += r;
        if (r == 0) break;
    }

    bool ok = true;
    for (const label i : cells_)
    {
        if (!out.admissible(i, gamma_))
        {
            rep.failedCell = i;
            rep.failure = out.whyInadmissible(i, gamma_)
              + " after the coupled pressure step";
            ok = false;
            break;
        }
    }
    if (par && !returnReduce(ok, andOp<bool>()) && ok)
    {
        rep.failure = "a cell of another rank is inadmissible after the"
            " coupled pressure step";
        ok = false;
    }
    return ok;
}


// ************************************************************************* //


// ************************************************************************* //
