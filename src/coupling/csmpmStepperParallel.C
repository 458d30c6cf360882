/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "csmpmStepper.H"
#include "mpmCloudIO.H"
#include "fvMesh.H"
#include "cloud.H"
#include "globalIndex.H"
#include "PstreamReduceOps.H"
#include <unordered_map>
#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::csmpmStepper::checkParallelCloud(bool found, bool idsRead)
{
    const Time& runTime = fvMesh_.time();
    if (!returnReduce(found, orOp<bool>()))
    {
        FatalErrorInFunction
            << "No particles: no processor directory holds an MPM cloud at "
            << runTime.timeName() << " (e.g. "
            << runTime.timePath()/cloud::prefix/cloudName_ << "), but"
            << " constant/mpmProperties exists. Seed one with"
            << " mpmSetParticles before decomposePar, or remove"
            << " constant/mpmProperties for a gas-only run"
            << exit(FatalError);
    }
    // A processor directory without its cloud: fewer particles than the
    // undecomposed cloud of the same time (decomposePar's input)
    const label nRanks = returnReduce(P_.size(), sumOp<label>());
    label nRoot = -1;
    if (Pstream::master())
    {
        nRoot = mpmCloudIO::countParticles
        (
            runTime.globalPath()/runTime.timeName()/cloud::prefix/cloudName_
        );
    }
    Pstream::scatter(nRoot);
    if (nRoot >= 0 && nRoot != nRanks)
    {
        FatalErrorInFunction
            << "The processor directories' clouds at " << runTime.timeName()
            << " hold " << nRanks << " particles; the undecomposed cloud "
            << runTime.globalPath()/runTime.timeName()/cloud::prefix
              /cloudName_ << " holds " << nRoot << ". A processor"
            << " directory lacks its cloud (or holds another"
            << " decomposition's): run decomposePar -force again"
            << exit(FatalError);
    }
    // Without the undecomposed cloud (a time written in parallel: every
    // rank writes its cloud, empty or not) every rank must hold one
    if (nRoot < 0 && !returnReduce(found, andOp<bool>()))
    {
        if (!found)
        {
            Pout<< "No MPM cloud in "
                << runTime.timePath()/cloud::prefix/cloudName_ << endl;
        }
        FatalErrorInFunction
            << "A processor directory lacks its MPM cloud at "
            << runTime.timeName() << " (the ranks without it are listed"
            << " above), and the case has no undecomposed cloud there to"
            << " tell an empty subdomain: the parallel run writes every"
            << " rank's cloud. Restart from another time, or decompose"
            << " again" << exit(FatalError);
    }
    if (nRanks == 0)
    {
        FatalErrorInFunction
            << "No particles: the MPM cloud at " << runTime.timeName()
            << " holds no particle. Seed some with mpmSetParticles"
            << exit(FatalError);
    }
    // A cloud without ids: number the particles across the ranks (the
    // deposit orders by id)
    if (!returnReduce(idsRead, andOp<bool>()))
    {
        const globalIndex gi(P_.size());
        forAll(P_.id, p) P_.id[p] = gi.toGlobal(p);
    }
}


// (3.20): J^g_{n+1} = J^g_n V_{n+1}/V_n with the volumes of G2P
void Foam::csmpmStepper::updateJg()
{
    if (!par_.valid())
    {
        forAll(P_.x, p) Jg_[p] *= P_.V[p]/Vold_[p];
        return;
    }

    // The particles before G2P by id; those still here update in place,
    // those that left send (id, J^g, V_old) to all ranks
    std::unordered_map<label, label> at;
    at.reserve(2*idOld_.size());
    forAll(idOld_, q) at[idOld_[q]] = q;
    const label nP = P_.size();
    List<scalar> JgNew(nP, scalar(-1));
    List<bool> stayed(idOld_.size(), false);
    DynamicList<label> missing;
    forAll(P_.x, p)
    {
        const auto it = at.find(P_.id[p]);
        if (it == at.end())
        {
            missing.append(p);
            continue;
        }
        const label q = it->second;
        JgNew[p] = Jg_[q]*(P_.V[p]/Vold_[q]);
        stayed[q] = true;
    }
    DynamicList<scalar> left;
    forAll(stayed, q)
    {
        if (stayed[q]) continue;
        left.append(scalar(idOld_[q]));
        left.append(Jg_[q]);
        left.append(Vold_[q]);
    }
    if (returnReduce(left.size(), sumOp<label>()) > 0)
    {
        List<List<scalar>> all(Pstream::nProcs());
        all[Pstream::myProcNo()] = left;
        Pstream::gatherList(all);
        Pstream::scatterList(all);
        std::unordered_map<label, std::pair<scalar, scalar>> moved;
        for (const List<scalar>& l : all)
        {
            for (label k = 0; k + 2 < l.size(); k += 3)
            {
                moved[label(std::llround(l[k]))] = {l[k + 1], l[k + 2]};
            }
        }
        for (const label p : missing)
        {
            const auto it = moved.find(P_.id[p]);
            if (it == moved.end())
            {
                FatalErrorInFunction
                    << "Particle id " << P_.id[p] << " arrived on processor "
                    << Pstream::myProcNo() << " without its J^g"
                    << exit(FatalError);
            }
            JgNew[p] = it->second.first*(P_.V[p]/it->second.second);
        }
    }
    else if (missing.size())
    {
        FatalErrorInFunction
            << missing.size() << " particles arrived on processor "
            << Pstream::myProcNo() << " without their J^g" << exit(FatalError);
    }

    Jg_.setSize(nP);
    forAll(JgNew, p) Jg_[p] = JgNew[p];
    lambdaG_.setSize(nP);
    forAll(P_.x, p)
    {
        lambdaG_[p] = lambdaGiven_
            ? lambdaValue_ : solver_.materials()[P_.material[p]].lambda();
    }
    pg_.setSize(nP);
    Kg_.setSize(nP);
    Vold_.setSize(nP);
}


// ************************************************************************* //
