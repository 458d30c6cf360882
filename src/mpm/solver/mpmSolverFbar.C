/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmSolver.H"
#include "mpmParallel.H"

// F-bar (Zhao et al. 2023b, as used in 2.3.4): the kernel-support average,
// the stress at F-bar and the penalty on the volume modes it does not see

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::mpmSolver::fbarWeightScale(const label p) const
{
    if (!fbarConvex_) return 1;
    scalar sum = 0;
    for (label j = kw_.start[p]; j < kw_.start[p + 1]; ++j)
    {
        sum += mag(kw_.w[j]);
    }
    return sum > 0 ? 1/sum : 0;
}


void Foam::mpmSolver::fbarAverage(const mpmParticles& P, UList<scalar>& f)
{
    const scalar tiny = VSMALL;
    forAll(materials_, k)
    {
        if (!materials_[k].Fbar()) continue;
        for (label p = materialStart_[k]; p < materialStart_[k + 1]; ++p)
        {
            for (label j = kw_.start[p]; j < kw_.start[p + 1]; ++j)
            {
                fbarMass_[kw_.vertex[j]] = 0;
                fbarSum_[kw_.vertex[j]] = 0;
            }
        }
    }
    if (par_)
    {
        // A shared vertex's copies are summed below: none may keep an
        // earlier call's value
        fbarMass_ = Zero;
        fbarSum_ = Zero;
    }
    forAll(materials_, k)
    {
        if (!materials_[k].Fbar()) continue;
        for (label p = materialStart_[k]; p < materialStart_[k + 1]; ++p)
        {
            const scalar r = fbarWeightScale(p);
            const scalar m = P.m[p];
            const scalar mf = m*f[p];
            for (label j = kw_.start[p]; j < kw_.start[p + 1]; ++j)
            {
                const label i = kw_.vertex[j];
                const scalar a = fbarConvex_ ? mag(kw_.w[j])*r : kw_.w[j];
                fbarMass_[i] += a*m;
                fbarSum_[i] += a*mf;
            }
        }
    }
    if (par_)
    {
        // The average over the kernel support of every rank's particles
        par_->sumShared(fbarMass_);
        par_->sumShared(fbarSum_);
    }
    forAll(materials_, k)
    {
        if (!materials_[k].Fbar()) continue;
        for (label p = materialStart_[k]; p < materialStart_[k + 1]; ++p)
        {
            const scalar r = fbarWeightScale(p);
            scalar s = 0;
            for (label j = kw_.start[p]; j < kw_.start[p + 1]; ++j)
            {
                const label i = kw_.vertex[j];
                if (mag(fbarMass_[i]) > tiny)
                {
                    const scalar a = fbarConvex_ ? mag(kw_.w[j])*r : kw_.w[j];
                    s += a*fbarSum_[i]/fbarMass_[i];
                }
            }
            f[p] = s;
        }
    }
}


void Foam::mpmSolver::fbarStress
(
    mpmParticles& P,
    const label k,
    const bool returnMap
)
{
    const mpmMaterial& mat = materials_[k];
    const label b = materialStart_[k];
    const label n = materialStart_[k + 1] - b;
    const tensor offAxes(mesh_.offAxes());
    const tensor onAxes(tensor::I - offAxes);
    const symmTensor Id(symm(onAxes));
    const scalar invDim = 1.0/mesh_.dim();

    // Fbar = (Jbar/J)^(1/dim) F; the scale kept in piBar_ for the plastic
    // models' F.  A non-positive average (negative kernel weights at an
    // extreme state) falls back to the particle's own J
    for (label p = b; p < b + n; ++p)
    {
        const scalar J = det(P.F[p])*P.Jp[p];
        if (!(Jbar_[p] > 0)) Jbar_[p] = J;
        const scalar alpha = std::pow(Jbar_[p]/J, invDim);
        Fbar_[p] = (offAxes + alpha*onAxes) & P.F[p];
        piBar_[p] = alpha;
    }

    SubList<tensor> Fb(Fbar_, n, b);
    SubList<symmTensor> sigma(P.sigma, n, b);
    SubList<scalar> psi(P.psi, n, b);
    if (mat.plastic())
    {
        SubList<scalar> epsilonP(P.epsilonP, n, b);
        SubList<scalar> Jp(P.Jp, n, b);
        mat.plasticStress(Fb, epsilonP, Jp, sigma, psi, returnMap);
        // F_e from the returned Fbar with the particle's own volume ratio
        if (returnMap)
        {
            for (label p = b; p < b + n; ++p)
            {
                P.F[p] = (offAxes + (1/piBar_[p])*onAxes) & Fbar_[p];
            }
        }
    }
    else
    {
        mat.stress(Fb, sigma, psi);
    }

    // The energy-consistent stress: Jbar/J dev(sigma(Fbar)) here, plus the
    // averaged mean stress (updateStress)
    for (label p = b; p < b + n; ++p)
    {
        const scalar J = det(P.F[p])*P.Jp[p];
        const symmTensor& s = P.sigma[p];
        const scalar pi = (s && Id)*invDim;
        P.sigma[p] = (Jbar_[p]/J)*(s - pi*Id);
        piBar_[p] = pi;
    }
}


// The F-bar's zero-energy volume modes held by a shear-stiff penalty
void Foam::mpmSolver::fbarStabilise(mpmParticles& P)
{
    // W = sum_p V0_p G/2 d_p^2, d = (I - A) J: its Cauchy stress
    // (1/V0_q) dW/dJ_q I = G (d - A d)_q I (A symmetric for one density)
    // d = J - Jbar (J = det(F) Jp: the return mapping kept it) and A d
    const label nP = P.size();
    drift_.setSize(nP);
    driftBar_.setSize(nP);
    forAll(materials_, k)
    {
        if (!materials_[k].Fbar()) continue;
        for (label p = materialStart_[k]; p < materialStart_[k + 1]; ++p)
        {
            drift_[p] = det(P.F[p])*P.Jp[p] - Jbar_[p];
            driftBar_[p] = drift_[p];
        }
    }
    fbarAverage(P, driftBar_);

    const symmTensor Id(symm(tensor::I - mesh_.offAxes()));
    forAll(materials_, k)
    {
        const mpmMaterial& mat = materials_[k];
        if (!mat.Fbar()) continue;
        const scalar G = mat.E()/(2*(1 + mat.nu()));
        for (label p = materialStart_[k]; p < materialStart_[k + 1]; ++p)
        {
            const scalar d = drift_[p];
            P.sigma[p] += G*(d - driftBar_[p])*Id;
            P.psi[p] += 0.5*G*d*d;
        }
    }
}


// ************************************************************************* //
