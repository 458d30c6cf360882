/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "lagrangianStepper.H"
#include "bsmsExport.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::lagrangianStepper::lagrangianStepper
(
    const lagrangianRecording& r,
    const dictionary& levels
)
:
    reference_(r.referenceGraph()),
    pooling_(levels),
    kind_(r.kind())
{
    pooling_.build(reference_);
    graph_.reset(new lagrangianGraph(reference_, kind_, r.worldRadius()));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

gnnTorch::trainerSettings Foam::lagrangianStepper::network
(
    const label latent,
    const label hidden
)
{
    gnnTorch::trainerSettings t;
    t.model = "bsms";
    t.world = 1;
    t.nIn = nIn;
    t.nOut = nOut;
    t.latent = latent;
    t.hidden = hidden;
    t.noiseStd = {0.0};
    return t;
}


Foam::lagrangianStepper::predictor Foam::lagrangianStepper::predictorOf
(
    gnnTorch::bsmsTrainerFacade& net
)
{
    return [&net](const std::vector<double>& in, const bsmsData::world& w)
    {
        net.setWorlds({&w});
        return net.predict(in);
    };
}


bsmsData::world Foam::lagrangianStepper::world(const pointField& x) const
{
    graph_->move(x);
    pooling_.setContact(graph_->worldEdges());
    return bsmsExportWorld(pooling_, x);
}


void Foam::lagrangianStepper::inputs
(
    const pointField& xPrev,
    const pointField& x,
    const pointField& xNext,
    double* in
) const
{
    forAll(x, i)
    {
        double* p = in + nIn*i;
        const vector v = x[i] - xPrev[i];
        const label k = label(kind_[i]);
        const bool act = kind_[i] == lagrangianGraph::nodeKind::actuator;
        const vector a = act ? vector(xNext[i] - x[i]) : vector::zero;
        for (direction d = 0; d < 3; ++d)
        {
            p[d] = v[d];
            p[3 + d] = (d == k ? 1 : 0);
            p[6 + d] = a[d];
        }
    }
}


bool Foam::lagrangianStepper::step
(
    const predictor& model,
    const pointField& xPrev,
    const pointField& x,
    const pointField& xNext,
    pointField& out,
    label& bad
) const
{
    const label n = x.size();
    std::vector<double> in(nIn*n);
    inputs(xPrev, x, xNext, in.data());
    const std::vector<double> dx = model(in, world(x));
    out.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        if (kind_[i] == lagrangianGraph::nodeKind::actuator)
        {
            // The prescribed path
            out[i] = xNext[i];
            continue;
        }
        for (direction d = 0; d < 3; ++d)
        {
            const double v = dx[nOut*i + d];
            if (!std::isfinite(v))
            {
                bad = i;
                return false;
            }
            out[i][d] = x[i][d] + v;
        }
    }
    return true;
}


// ************************************************************************* //
