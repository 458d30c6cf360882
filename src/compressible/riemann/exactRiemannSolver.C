/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "exactRiemannSolver.H"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::exactRiemannSolver::pressureFunction
(
    double p,
    const state& K,
    double cK,
    double& f,
    double& df
) const
{
    const double g = gamma_;
    if (p > K.p)
    {
        // Shock: Rankine-Hugoniot
        const double A = 2/((g + 1)*K.rho);
        const double B = (g - 1)/(g + 1)*K.p;
        const double q = std::sqrt(A/(p + B));
        f = (p - K.p)*q;
        df = q*(1 - 0.5*(p - K.p)/(p + B));
    }
    else
    {
        // Rarefaction: isentropic
        const double r = p/K.p;
        f = 2*cK/(g - 1)*(std::pow(r, (g - 1)/(2*g)) - 1);
        df = 1/(K.rho*cK)*std::pow(r, -(g + 1)/(2*g));
    }
}


// * * * * * * * * * * * * * * * * Constructor * * * * * * * * * * * * * * //

Foam::exactRiemannSolver::exactRiemannSolver
(
    const state& left,
    const state& right,
    double gamma
)
:
    L_(left),
    R_(right),
    gamma_(gamma),
    iterations_(0)
{
    if (!(left.rho > 0) || !(right.rho > 0) || !(left.p > 0) || !(right.p > 0))
    {
        throw std::invalid_argument
        (
            "exactRiemannSolver: density and pressure must be positive"
        );
    }
    if (!(gamma > 1))
    {
        throw std::invalid_argument("exactRiemannSolver: gamma must be > 1");
    }
    const double g = gamma_;
    cL_ = std::sqrt(g*L_.p/L_.rho);
    cR_ = std::sqrt(g*R_.p/R_.rho);

    // Pressure positivity condition: no vacuum generated
    if (2*(cL_ + cR_)/(g - 1) <= R_.u - L_.u)
    {
        throw std::invalid_argument
        (
            "exactRiemannSolver: the data generate a vacuum"
            " (2 (cL + cR)/(gamma - 1) <= uR - uL)"
        );
    }

    // Start from the two-rarefaction approximation (always positive)
    const double z = (g - 1)/(2*g);
    double p =
        std::pow
        (
            (cL_ + cR_ - 0.5*(g - 1)*(R_.u - L_.u))
           /(cL_/std::pow(L_.p, z) + cR_/std::pow(R_.p, z)),
            1/z
        );

    const double du = R_.u - L_.u;
    for (iterations_ = 1; iterations_ <= 100; ++iterations_)
    {
        double fL, dfL, fR, dfR;
        pressureFunction(p, L_, cL_, fL, dfL);
        pressureFunction(p, R_, cR_, fR, dfR);
        double pNew = p - (fL + fR + du)/(dfL + dfR);
        if (pNew < 0) pNew = 1e-12*p;
        const double change = 2*std::abs(pNew - p)/(pNew + p);
        p = pNew;
        if (change < 1e-14) break;
    }
    pStar_ = p;

    double fL, dfL, fR, dfR;
    pressureFunction(pStar_, L_, cL_, fL, dfL);
    pressureFunction(pStar_, R_, cR_, fR, dfR);
    uStar_ = 0.5*(L_.u + R_.u) + 0.5*(fR - fL);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

double Foam::exactRiemannSolver::rhoStarLeft() const
{
    const double g = gamma_;
    const double r = pStar_/L_.p;
    if (pStar_ > L_.p)
    {
        const double k = (g - 1)/(g + 1);
        return L_.rho*(r + k)/(k*r + 1);
    }
    return L_.rho*std::pow(r, 1/g);
}


double Foam::exactRiemannSolver::rhoStarRight() const
{
    const double g = gamma_;
    const double r = pStar_/R_.p;
    if (pStar_ > R_.p)
    {
        const double k = (g - 1)/(g + 1);
        return R_.rho*(r + k)/(k*r + 1);
    }
    return R_.rho*std::pow(r, 1/g);
}


Foam::exactRiemannSolver::state
Foam::exactRiemannSolver::sample(double s) const
{
    const double g = gamma_;

    if (s <= uStar_)
    {
        // Left of the contact
        if (pStar_ > L_.p)
        {
            const double sL = L_.u - cL_*std::sqrt
            (
                (g + 1)/(2*g)*pStar_/L_.p + (g - 1)/(2*g)
            );
            return s <= sL ? L_ : state{rhoStarLeft(), uStar_, pStar_};
        }
        const double sHead = L_.u - cL_;
        const double cStar = cL_*std::pow(pStar_/L_.p, (g - 1)/(2*g));
        const double sTail = uStar_ - cStar;
        if (s <= sHead) return L_;
        if (s >= sTail) return {rhoStarLeft(), uStar_, pStar_};
        // Inside the left fan
        const double c = 2/(g + 1)*(cL_ + 0.5*(g - 1)*(L_.u - s));
        const double rho = L_.rho*std::pow(c/cL_, 2/(g - 1));
        return {rho, 2/(g + 1)*(cL_ + 0.5*(g - 1)*L_.u + s),
                L_.p*std::pow(c/cL_, 2*g/(g - 1))};
    }

    // Right of the contact
    if (pStar_ > R_.p)
    {
        const double sR = R_.u + cR_*std::sqrt
        (
            (g + 1)/(2*g)*pStar_/R_.p + (g - 1)/(2*g)
        );
        return s >= sR ? R_ : state{rhoStarRight(), uStar_, pStar_};
    }
    const double sHead = R_.u + cR_;
    const double cStar = cR_*std::pow(pStar_/R_.p, (g - 1)/(2*g));
    const double sTail = uStar_ + cStar;
    if (s >= sHead) return R_;
    if (s <= sTail) return {rhoStarRight(), uStar_, pStar_};
    // Inside the right fan
    const double c = 2/(g + 1)*(cR_ - 0.5*(g - 1)*(R_.u - s));
    const double rho = R_.rho*std::pow(c/cR_, 2/(g - 1));
    return {rho, 2/(g + 1)*(-cR_ + 0.5*(g - 1)*R_.u + s),
            R_.p*std::pow(c/cR_, 2*g/(g - 1))};
}


std::vector<Foam::exactRiemannSolver::state>
Foam::exactRiemannSolver::sample
(
    const std::vector<double>& x,
    double x0,
    double t
) const
{
    if (!(t > 0))
    {
        throw std::invalid_argument("exactRiemannSolver: sample at t > 0");
    }
    std::vector<state> out(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        out[i] = sample((x[i] - x0)/t);
    }
    return out;
}


// ************************************************************************* //
