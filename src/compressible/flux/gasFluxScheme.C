/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "gasFluxScheme.H"
#include "dictionaryChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(gasFluxScheme, 0);
    defineRunTimeSelectionTable(gasFluxScheme, dictionary);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// (3.1-3.3) flux along direction n of one state, and its largest speed
inline void stateFlux
(
    const double q[5],
    int n,
    double gamma,
    bool advective,
    double f[5],
    double& lambda,
    double& unOut,
    double& cOut
)
{
    const double rho = q[0];
    const double un = q[1 + n]/rho;
    const double p =
        (gamma - 1)*(q[4] - 0.5*(q[1]*q[1] + q[2]*q[2] + q[3]*q[3])/rho);
    f[0] = q[0]*un;
    f[1] = q[1]*un;
    f[2] = q[2]*un;
    f[3] = q[3]*un;
    f[4] = q[4]*un;
    unOut = un;
    cOut = std::sqrt(std::abs(gamma*p/rho));
    if (advective)
    {
        lambda = std::abs(un);
    }
    else
    {
        f[1 + n] += p;
        f[4] += p*un;
        lambda = std::abs(un) + cOut;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gasFluxScheme::gasFluxScheme(const dictionary& dict)
:
    characteristic_(true)
{
    characteristic_ =
        dictionaryChecks::getWordOf
        (
            dict, "variables", "characteristic",
            {"characteristic", "component"}
        )
     == "characteristic";
}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::gasFluxScheme::physicalFluxes(const gasLine& line) const
{
    const label N = line.L + 2*line.G;
    if (label(lambda_.size()) < N)
    {
        for (auto& f : f_) f.resize(N);
        lambda_.resize(N);
        un_.resize(N);
        c_.resize(N);
    }
    double q[5], f[5];
    for (label i = 0; i < N; ++i)
    {
        for (int c = 0; c < 5; ++c) q[c] = line.q[c][i];
        stateFlux
        (
            q, line.normal, line.gamma, line.advective, f, lambda_[i],
            un_[i], c_[i]
        );
        for (int c = 0; c < 5; ++c) f_[c][i] = f[c];
    }
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::gasFluxScheme> Foam::gasFluxScheme::New
(
    const dictionary& dict
)
{
    word name;
    auto ctor = dictionaryChecks::selectConstructor
    (
        dict, "scheme", *dictionaryConstructorTablePtr_, name
    );
    return autoPtr<gasFluxScheme>(ctor(dict));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::gasFluxScheme::firstOrderFlux
(
    const double qL[5],
    const double qR[5],
    label normal,
    double gamma,
    bool advective,
    double F[5]
)
{
    double fL[5], fR[5], lL, lR, un, c;
    stateFlux(qL, normal, gamma, advective, fL, lL, un, c);
    stateFlux(qR, normal, gamma, advective, fR, lR, un, c);
    const double alpha = std::max(lL, lR);
    for (int c = 0; c < 5; ++c)
    {
        F[c] = 0.5*(fL[c] + fR[c]) - 0.5*alpha*(qR[c] - qL[c]);
    }
}


// ************************************************************************* //
