/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
-------------------------------------------------------------------------------
    barrierContact: the per-step work (barrier forces, friction, the time
    step limit, the step check); the setup is in barrierContactSetup.C
\*---------------------------------------------------------------------------*/

#include "barrierContact.H"
#include "ops.H"
#include <chrono>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::barrierContact::crossesZone
(
    const label c,
    const vector& x0,
    const vector& x1
) const
{
    const label nPatches = patchNames_.size();
    for (label j = cellStart_[c]; j < cellStart_[c + 1]; ++j)
    {
        const face& f = faces_[cellFaces_[j]];
        if (f.patch >= nPatches && pathMeets(f, x0, x1)) return true;
    }
    return false;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::label Foam::barrierContact::nContactCells() const
{
    label n = 0;
    for (label c = 0; c < mesh_.nCells(); ++c)
    {
        if (nearWall(c)) ++n;
    }
    return n;
}


void Foam::barrierContact::forces
(
    const mpmParticles& P,
    const kernelWeights& kw,
    UList<vector>& f
)
{
    const auto t0 = std::chrono::steady_clock::now();
    nWithin_ = 0;
    nExamined_ = 0;
    const scalar dHat = dHat_;
    const scalar kScale = stiffness_/(dHat*dHat);
    const scalar dFloor = 1e-12*dHat;
    const label nP = P.size();
    const bool friction = friction_ > 0;
    dStart_.setSize(nP);
    nStart_.setSize(nP);
    disp_.setSize(nP);
    cacheValid_ = true;
    if (friction)
    {
        lambda_.setSize(nP);
        if (bound_.size() != mesh_.nVertices())
        {
            bound_.setSize(mesh_.nVertices(), Zero);
            normal_.setSize(mesh_.nVertices(), Zero);
            fFriction_.setSize(mesh_.nVertices(), Zero);
        }
    }

    for (label p = 0; p < nP; ++p)
    {
        const label c = P.cell[p];
        f[p] = Zero;
        dStart_[p] = GREAT;
        disp_[p] = 0;
        if (friction) lambda_[p] = 0;
        if (!nearWall(c)) continue;

        // Farther than dHat from every face if the cell's centre is far
        // enough: d >= d(centre) - |x - centre| (a lower bound kept)
        const vector x = mesh_.inPlane(P.x[p]);
        const scalar dLow = cellDistance_[c] - mag(x - cellCentre_[c]);
        if (dLow >= dHat)
        {
            dStart_[p] = dLow;
            nStart_[p] = Zero;
            continue;
        }
        ++nExamined_;

        const scalar kappa = kScale*E_[P.material[p]]*P.V0[p];
        vector fp(Zero);
        scalar lambdaSum = 0;

        label j = cellStart_[c];
        const label end = cellStart_[c + 1];
        while (j < end)
        {
            // The nearest face of this patch
            const label patch = faces_[cellFaces_[j]].patch;
            scalar d2 = GREAT;
            vector xc(Zero);
            label best = -1;
            for (; j < end && faces_[cellFaces_[j]].patch == patch; ++j)
            {
                const vector q = nearest(faces_[cellFaces_[j]], x);
                const scalar s = magSqr(x - q);
                if (s < d2)
                {
                    d2 = s;
                    xc = q;
                    best = cellFaces_[j];
                }
            }
            const scalar d = std::sqrt(d2);
            minDistance_ = min(minDistance_, d);
            const vector n = d > dFloor ? (x - xc)/d : -faces_[best].nOut;
            if (d < dStart_[p])
            {
                dStart_[p] = d;
                nStart_[p] = n;
            }
            if (d >= dHat) continue;

            // (IPC barrier) f_n = -kappa b'(d) n
            const scalar lambda = -kappa*barrierD1(max(d, dFloor), dHat);
            fp += lambda*n;
            lambdaSum += lambda;
        }
        if (lambdaSum > 0) ++nWithin_;
        f[p] = fp;

        // The friction bound mu lambda and the normal at the vertices
        if (friction && lambdaSum > 0)
        {
            lambda_[p] = lambdaSum;
            const scalar muLambda = friction_*lambdaSum;
            for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
            {
                const scalar w = max(kw.w[k], scalar(0));
                if (w <= 0) continue;
                const label i = kw.vertex[k];
                if (bound_[i] == 0) touched_.append(i);
                bound_[i] += w*muLambda;
                normal_[i] += w*fp;
            }
        }
    }

    forceTime_ += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
    ++nForceCalls_;
    nWithinSum_ += nWithin_;
    nExaminedSum_ += nExamined_;
}


void Foam::barrierContact::friction
(
    const UList<scalar>& mass,
    const UList<label>& vertices,
    const scalar dt,
    UList<vector>& velocity
)
{
    if (friction_ <= 0) return;
    const auto t0 = std::chrono::steady_clock::now();
    const scalar epsV = epsV_;
    for (const label i : vertices)
    {
        const scalar B = bound_[i];
        const scalar m = mass[i];
        fFriction_[i] = Zero;
        if (!(B > 0) || !(m > VSMALL)) continue;
        const scalar nMag = mag(normal_[i]);
        if (!(nMag > VSMALL)) continue;
        const vector n = normal_[i]/nMag;
        const vector& v = velocity[i];
        const vector vt = v - (v & n)*n;
        const scalar ut = mag(vt);
        if (!(ut > VSMALL)) continue;

        // Backward Euler for the smoothed Coulomb friction with the lagged
        // bound B = sum w mu lambda: m (u - ut) = -dt B f1(u/epsV), u in
        // [0, ut]: sliding (u >= epsV) or the root of the quadratic
        const scalar k = dt*B;
        scalar u = ut - k/m;
        if (u < epsV)
        {
            const scalar b = m + 2*k/epsV;
            const scalar disc = max(b*b - 4*k*m*ut/(epsV*epsV), scalar(0));
            u = 2*m*ut/(b + std::sqrt(disc));
        }
        u = min(max(u, scalar(0)), ut);
        const vector dv = (u/ut - 1)*vt;
        frictionWork_ += 0.5*m*(magSqr(v) - magSqr(v + dv));
        velocity[i] += dv;
        fFriction_[i] = (m/dt)*dv;
    }
    forceTime_ += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - t0
    ).count();
}


void Foam::barrierContact::frictionShare
(
    const mpmParticles& P,
    const kernelWeights& kw,
    UList<vector>& f
)
{
    if (friction_ <= 0) return;
    const label nP = P.size();
    for (label p = 0; p < nP; ++p)
    {
        const scalar muLambda = friction_*lambda_[p];
        if (muLambda <= 0) continue;
        vector ft(Zero);
        for (label k = kw.start[p]; k < kw.start[p + 1]; ++k)
        {
            const scalar w = max(kw.w[k], scalar(0));
            const label i = kw.vertex[k];
            if (w > 0 && bound_[i] > 0)
            {
                ft += (w*muLambda/bound_[i])*fFriction_[i];
            }
        }
        f[p] += ft;
    }
}


void Foam::barrierContact::resetVertices(const UList<label>& vertices)
{
    for (const label i : vertices)
    {
        bound_[i] = 0;
        normal_[i] = Zero;
        fFriction_[i] = Zero;
    }
    touched_.clear();
}


Foam::scalar Foam::barrierContact::maxDeltaT
(
    const mpmParticles& P,
    const scalar CFL
) const
{
    scalar dt = GREAT;
    const scalar dHat = dHat_;
    const scalar kScale = stiffness_/(dHat*dHat);
    const scalar dFloor = 1e-12*dHat;
    const label nP = P.size();

    // The last step's distances less the step's displacement (a lower
    // bound of the distance now), when they belong to these particles
    if (cacheValid_ && dStart_.size() == nP)
    {
        for (label p = 0; p < nP; ++p)
        {
            if (dStart_[p] >= GREAT) continue;
            const scalar d = max(dStart_[p] - disp_[p], dFloor);
            if (d < dHat)
            {
                const scalar kappa = kScale*E_[P.material[p]]*P.V0[p];
                const scalar k = kappa*barrierD2(d, dHat);
                if (k > 0) dt = min(dt, CFL*std::sqrt(P.m[p]/k));
            }
            const scalar vn = -(P.v[p] & nStart_[p]);
            if (vn > 0) dt = min(dt, 0.5*d/vn);
        }
        return dt;
    }

    for (label p = 0; p < nP; ++p)
    {
        const label c = P.cell[p];
        if (c < 0 || !nearWall(c)) continue;
        const vector x = mesh_.inPlane(P.x[p]);
        const vector v = mesh_.inPlane(P.v[p]);
        const scalar kappa = kScale*E_[P.material[p]]*P.V0[p];

        label j = cellStart_[c];
        const label end = cellStart_[c + 1];
        while (j < end)
        {
            const label patch = faces_[cellFaces_[j]].patch;
            scalar d2 = GREAT;
            vector xc(Zero);
            for (; j < end && faces_[cellFaces_[j]].patch == patch; ++j)
            {
                const vector q = nearest(faces_[cellFaces_[j]], x);
                const scalar s = magSqr(x - q);
                if (s < d2) { d2 = s; xc = q; }
            }
            const scalar d = max(std::sqrt(d2), dFloor);
            if (d < dHat)
            {
                // The barrier spring kappa b''(d) on the particle's mass
                const scalar k = kappa*barrierD2(d, dHat);
                if (k > 0) dt = min(dt, CFL*std::sqrt(P.m[p]/k));
            }
            // Step filter: at most half the distance towards the wall
            const scalar vn = -(v & (x - xc))/d;
            if (vn > 0) dt = min(dt, 0.5*d/vn);
        }
    }
    return dt;
}


Foam::label Foam::barrierContact::check
(
    const mpmParticles& P,
    const UList<vector>& vGrid,
    const scalar dt,
    scalar& dist
) const
{
    const label nP = P.size();
    const bool cached = cacheValid_ && dStart_.size() == nP;
    const bool zones = !zoneNames_.empty();
    for (label p = 0; p < nP; ++p)
    {
        const label c = P.cell[p];
        if (!nearWall(c)) continue;
        const scalar move = dt*mag(mesh_.inPlane(vGrid[p]));
        if (cached)
        {
            disp_[p] = move;
            // d(x + dx) >= d(x) - |dx|: only a particle that moves at least
            // its distance can reach the wall
            if (dStart_[p] > move) continue;
        }
        const vector xNew = P.x[p] + dt*vGrid[p];
        const label cNew = mesh_.findCell(xNew, c);
        if (cNew < 0)
        {
            dist = -1;
            return p;
        }
        // Through a zone face (inside the mesh): tested against the faces
        // listed for the path's end cells (all faces within dHat of them)
        if (zones)
        {
            const vector x0 = mesh_.inPlane(P.x[p]);
            const vector x1 = mesh_.inPlane(xNew);
            if (crossesZone(c, x0, x1) || crossesZone(cNew, x0, x1))
            {
                dist = 0;
                return p;
            }
        }
        const vector x = mesh_.inPlane(xNew);
        scalar d2 = GREAT;
        for (label j = cellStart_[c]; j < cellStart_[c + 1]; ++j)
        {
            d2 = min(d2, magSqr(x - nearest(faces_[cellFaces_[j]], x)));
        }
        const scalar d = std::sqrt(d2);
        minDistance_ = min(minDistance_, d);
        if (!(d > 0))
        {
            dist = d;
            return p;
        }
    }
    return -1;
}


// ************************************************************************* //
