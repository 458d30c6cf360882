/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "inversionClamp.H"
#include "henckyStrain.H"
#include "dictionaryChecks.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::inversionClamp::inversionClamp
(
    const dictionary& dict,
    const tensor& offAxes
)
:
    clamp_(true),
    minStretch_(0.1),
    maxShare_(0.01),
    offAxes_(offAxes)
{
    using namespace dictionaryChecks;

    if (!dict.found("inversion", keyType::LITERAL)) return;
    const dictionary* d = dict.findDict("inversion", keyType::LITERAL);
    if (!d)
    {
        badEntry(dict, "inversion", entryText(dict, "inversion"),
            "a sub-dictionary { treatment clamp; minStretch 0.1;"
            " maxShare 0.01; }");
    }
    clamp_ = getWordOf(*d, "treatment", "clamp", {"clamp", "stop"}) == "clamp";
    minStretch_ = getInRange(*d, "minStretch", 0.1, 0, 1);
    if (!(minStretch_ < 1))
    {
        badEntry(*d, "minStretch", Foam::name(minStretch_),
            "a number 0 < minStretch < 1 (1 would clamp every compression)");
    }
    maxShare_ = getInRange(*d, "maxShare", 0.01, 0, 1);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::inversionClamp::signedSVD
(
    const tensor& F,
    tensor& U,
    vector& s,
    tensor& V,
    bool offAxis[3]
) const
{
    // V and the stretches squared from C = F^T F (Jacobi: plane strain's
    // C never mixes the unsolved axis in)
    vector lambda;
    tensor Q;
    henckyStrain::eigenSymm(symm(F.T() & F), lambda, Q);

    vector v[3], u[3];
    scalar sigma[3];
    label c = -1;
    for (label i = 0; i < 3; ++i)
    {
        v[i] = vector(Q(0, i), Q(1, i), Q(2, i));
        sigma[i] = std::sqrt(max(lambda[i], scalar(0)));
        offAxis[i] = magSqr(offAxes_ & v[i]) > 0.5;
        // The sign goes to the smallest stretch of a solved axis
        if (!offAxis[i] && (c < 0 || sigma[i] < sigma[c])) c = i;
    }
    label a = (c + 1) % 3;
    label b = (c + 2) % 3;
    if (sigma[b] > sigma[a]) std::swap(a, b);

    // V a rotation over the slots (a, b, c)
    if (((v[a] ^ v[b]) & v[c]) < 0) v[c] = -v[c];

    // U from F v_i = s_i u_i for the larger two; where F v_i vanishes
    // (a particle crushed to a line) any direction orthogonal will do
    const vector Fa(F & v[a]);
    u[a] = mag(Fa) > VSMALL ? Fa/mag(Fa) : v[a];
    vector w((F & v[b]) - ((F & v[b]) & u[a])*u[a]);
    if (!(mag(w) > 1e-12*max(sigma[a], VSMALL)))
    {
        w = v[b] - (v[b] & u[a])*u[a];
        if (mag(w) < 1e-6) w = v[c] - (v[c] & u[a])*u[a];
    }
    u[b] = w/mag(w);
    // U a rotation over the same slots: s_c carries the sign of det F
    u[c] = u[a] ^ u[b];

    for (label i = 0; i < 3; ++i)
    {
        s[i] = u[i] & (F & v[i]);
        for (label r = 0; r < 3; ++r)
        {
            U(r, i) = u[i][r];
            V(r, i) = v[i][r];
        }
    }
}


// (Irving, Teran and Fedkiw 2004) the stretches of the sign-corrected SVD
// clamped from below
bool Foam::inversionClamp::apply(tensor& F) const
{
    tensor U, V;
    vector s;
    bool offAxis[3];
    signedSVD(F, U, s, V, offAxis);

    bool changed = false;
    for (label i = 0; i < 3; ++i)
    {
        if (offAxis[i] || s[i] >= minStretch_) continue;
        // F + (s' - s) u v^T: the other stretches (and F_zz = 1 in plane
        // strain) stay exactly as they were
        const vector ui(U(0, i), U(1, i), U(2, i));
        const vector vi(V(0, i), V(1, i), V(2, i));
        F += (minStretch_ - s[i])*(ui*vi);
        changed = true;
    }
    return changed;
}


// ************************************************************************* //
