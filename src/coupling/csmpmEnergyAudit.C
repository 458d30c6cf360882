/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "csmpmEnergyAudit.H"
#include "messageStream.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

const char* const Foam::csmpmEnergyAudit::names[nStages] =
    {
        "P2G", "advection", "coupled solve", "grid update", "G2P",
        "solid substeps"
    };


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

void Foam::csmpmEnergyAudit::accept()
{
    if (!started_)
    {
        initial_ = gas_[0] + kinetic_[0] + kineticOut_[0] + elastic_[0];
        started_ = true;
    }
    // The particles' elastic energy changes only in G2P (F's update); it is
    // the work of the grid update's elastic forces, so it is booked there
    const double dElastic = elastic_[g2p + 1] - elastic_[g2p];
    for (label k = 0; k < nStages; ++k)
    {
        double d =
            (gas_[k + 1] - gas_[k])
          + (kinetic_[k + 1] - kinetic_[k])
          + (kineticOut_[k + 1] - kineticOut_[k])
          + (elastic_[k + 1] - elastic_[k]);
        if (k == gridUpdate) d += dElastic;
        if (k == g2p) d -= dElastic;
        sum_[k] += d;
    }
    gasInSolve_ += gas_[coupledSolve + 1] - gas_[coupledSolve];
    ghostChange_ += ghost_[1] - ghost_[0];
    ++nSteps_;
}


void Foam::csmpmEnergyAudit::report(const char* when) const
{
    if (!on_) return;
    const double E0 = initial_ != 0 ? initial_ : 1;
    double total = 0;
    const std::streamsize precision = Info().precision(15);
    Info<< "CSMPM energy audit (" << when << ", " << nSteps_
        << " steps; change of gas + solid energy by stage, relative to"
        << " the initial " << initial_ << "):";
    for (label k = 0; k < nStages; ++k)
    {
        Info<< "  " << names[k] << " " << sum_[k]/E0;
        if (k == coupledSolve)
        {
            Info<< " (gas " << gasInSolve_/E0 << ")";
        }
        total += sum_[k];
    }
    Info<< "  total " << total/E0
        << "; the ghost pressure's stored energy (not in the totals) "
        << ghostChange_/E0 << nl;
    Info().precision(precision);
}


// ************************************************************************* //
