/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "pressureFaceAssembly.H"
#include "cartesianMesh.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

// (3.21) on each face's passable share into (3.22)
void Foam::pressureFaceAssembly::assemble
(
    const cartesianMesh& mesh,
    const PtrList<gasBoundary>& bcs,
    const gasState& Ustar,
    const std::vector<double>& ghosts,
    const std::vector<label>& unknownOf,
    const scalar dt,
    const vector& g,
    pressureSystem& sys,
    std::vector<double> rhoF[3],
    std::vector<double> uStarF[3],
    std::vector<double> uF[3]
) const
{
    const std::vector<double>& rho = Ustar.q[0];

    // The gas's own density: its content over the cell's open volume
    auto density = [&](const label i)
    {
        return cellSolid
            ? rho[i]/std::max(1 - (*cellSolid)[i], openMin)
            : rho[i];
    };

    for (label d = 0; d < 3; ++d)
    {
        if (!mesh.active(d)) continue;
        const scalar V = mesh.cellVolume();
        const scalar A = V/mesh.dx(d);
        const scalar dx = mesh.dx(d);
        const std::vector<double>& mom = Ustar.q[1 + d];
        std::vector<double>* uB =
            alsoBoundaryVelocity ? alsoBoundaryVelocity + d : nullptr;

        // The face's share; rho_f and u*_f are kept whatever it is
        auto share = [&](const label f)
        {
            return faceShare ? faceShare[d][f] : 1.0;
        };

        auto coupleCells = [&](const label f, const label l, const label r)
        {
            const double rf = 0.5*(density(l) + density(r));
            double uS = 0.5*(mom[l]/rho[l] + mom[r]/rho[r]);
            // (so a face in hydrostatic balance stays at rest)
            if (bodyForce) uS += dt*g[d];
            rhoF[d][f] = rf;
            uStarF[d][f] = uS;
            const double a = share(f);
            if (a <= 0 || !gasCouplings) return;
            const label kl = unknownOf[l], kr = unknownOf[r];
            sys.couple(kl, kr, a*A/(rf*dx));
            sys.source[kl] -= a*A*uS/dt;
            sys.source[kr] += a*A*uS/dt;
        };

        // A processor face: the neighbour rank's cell is one side
        auto coupleGhost =
            [&](const label f, const label slot, const label i, bool low)
        {
            const double* gh = ghosts.data() + 5*slot;
            const double dG = slotSolid
                ? gh[0]/std::max(1 - (*slotSolid)[slot], openMin)
                : gh[0];
            const double dI = density(i);
            const double rf = low ? 0.5*(dG + dI) : 0.5*(dI + dG);
            const double uG = gh[1 + d]/gh[0];
            const double uI = mom[i]/rho[i];
            double uS = low ? 0.5*(uG + uI) : 0.5*(uI + uG);
            if (bodyForce) uS += dt*g[d];
            rhoF[d][f] = rf;
            uStarF[d][f] = uS;
            const double a = share(f);
            if (a <= 0 || !gasCouplings) return;
            const label k = unknownOf[i];
            sys.coupleRemote(k, slot, a*A/(rf*dx));
            if (low) sys.source[k] += a*A*uS/dt;
            else sys.source[k] -= a*A*uS/dt;
        };

        // A boundary face: its condition's velocity, into the source
        auto boundaryEnd =
            [&](const label f, const label i, const label patch, bool low)
        {
            double q[5];
            for (int c = 0; c < 5; ++c) q[c] = Ustar.q[c][i];
            const double u = bcs[patch].faceVelocity(q, d);
            uF[d][f] = u;
            if (uB) (*uB)[f] = u;
            if (low) sys.source[unknownOf[i]] += A*u/dt;
            else sys.source[unknownOf[i]] -= A*u/dt;
        };

        forEachFace
        (
            mesh, bcs, d, coupleCells, [](label, label) {}, boundaryEnd,
            coupleGhost
        );
    }
}


// ************************************************************************* //
