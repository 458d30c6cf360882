/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "bsmsInputRange.H"
#include <cmath>
#include <cstdio>
#include <limits>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bsmsInputRange::bsmsInputRange
(
    const bsmsModelSpec& spec,
    const std::vector<double>& used,
    const std::vector<double>& mean,
    const std::vector<double>& std,
    const long nSamples,
    const double nStd
)
:
    field_(spec.nState(), -1),
    component_(spec.nState()),
    fields_(spec.inputFields),
    lo_(spec.nState(), 0.0),
    hi_(spec.nState(), 0.0),
    mean_(spec.nState(), 0.0),
    std_(spec.nState(), 1.0),
    checked_(spec.nState(), false),
    recorded_(spec.inputMin.size() == spec.nState()),
    nStd_(nStd),
    active_
    (
        nSamples > 0
     && label(mean.size()) >= spec.nState()
     && label(std.size()) >= spec.nState()
    ),
    warned_(spec.inputFields.size(), false),
    worst_(spec.inputFields.size(), 0.0),
    worstTime_(spec.inputFields.size(), 0.0)
{
    static const char* xyz[3] = {"x", "y", "z"};
    label o = 0;
    forAll(spec.inputFields, i)
    {
        const label nc = spec.inputComponents[i];
        for (label c = 0; c < nc; ++c)
        {
            const label k = o + c;
            field_[k] = i;
            component_[k] = nc == 3 ? word(xyz[c]) : word::null;
            checked_[k] = active_ && used[k] != 0;
            if (!active_) continue;
            mean_[k] = mean[k];
            std_[k] = std[k];
            lo_[k] = recorded_ ? spec.inputMin[k] : mean[k] - 10*std[k];
            hi_[k] = recorded_ ? spec.inputMax[k] : mean[k] + 10*std[k];
        }
        o += nc;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::DynamicList<Foam::string> Foam::bsmsInputRange::check
(
    const std::vector<double>& state,
    const scalar t
)
{
    DynamicList<string> msgs;
    if (!active_) return msgs;

    const label nS = field_.size();
    const label nCells = label(state.size())/max(nS, label(1));
    const double inf = std::numeric_limits<double>::infinity();

    // The farthest value of each field: distance, component, cell
    List<double> far(fields_.size(), 0.0);
    labelList farComp(fields_.size(), -1);
    labelList farCell(fields_.size(), -1);
    for (label k = 0; k < nCells; ++k)
    {
        const double* s = state.data() + std::size_t(k)*nS;
        for (label c = 0; c < nS; ++c)
        {
            if (!checked_[c]) continue;
            const double x = s[c];
            const double beyond =
                std::isfinite(x) ? std::max(lo_[c] - x, x - hi_[c]) : inf;
            const double z = beyond/std_[c];
            const label f = field_[c];
            if (z > far[f])
            {
                far[f] = z;
                farComp[f] = c;
                farCell[f] = k;
            }
        }
    }

    forAll(fields_, f)
    {
        if (far[f] > worst_[f])
        {
            worst_[f] = far[f];
            worstTime_[f] = t;
        }
        if (warned_[f] || !(far[f] > nStd_)) continue;
        warned_[f] = true;

        const label c = farComp[f];
        const double x = state[std::size_t(farCell[f])*nS + c];
        const word name
        (
            component_[c].empty() ? fields_[f] : fields_[f] + "_" + component_[c]
        );
        char value[32], dist[32];
        if (std::isfinite(x))
        {
            std::snprintf(value, sizeof(value), "%.4g", x);
            std::snprintf(dist, sizeof(dist), "%.3g", far[f]);
        }
        else
        {
            std::snprintf(value, sizeof(value), "(non-finite)");
            std::snprintf(dist, sizeof(dist), "infinitely many");
        }
        char buf[512];
        std::snprintf
        (
            buf, sizeof(buf),
            "the input field %s is outside the model's training range at"
            " t = %g: %s = %s at cell %d lies %s standard deviations beyond"
            " the training range [%.4g, %.4g] of %s (%s; mean %.4g, std"
            " %.4g%s; warned beyond %g std). The model was not trained on"
            " such states: its predictions may mean little",
            fields_[f].c_str(), double(t), name.c_str(), value,
            int(farCell[f]), dist, lo_[c], hi_[c], name.c_str(),
            recorded_
          ? "the training states' extremes"
          : "mean +- 10 std: the model dictionary records no inputMin/inputMax",
            mean_[c], std_[c],
            std_[c] <= 1e-7 ? ", constant in the training data" : "",
            nStd_
        );
        msgs.append(buf);
    }
    return msgs;
}


Foam::DynamicList<Foam::string> Foam::bsmsInputRange::summary() const
{
    DynamicList<string> msgs;
    forAll(fields_, f)
    {
        if (!warned_[f]) continue;
        char buf[200];
        if (std::isfinite(worst_[f]))
        {
            std::snprintf
            (
                buf, sizeof(buf),
                "the input field %s went up to %.3g standard deviations"
                " beyond its training range (at t = %g)",
                fields_[f].c_str(), worst_[f], double(worstTime_[f])
            );
        }
        else
        {
            std::snprintf
            (
                buf, sizeof(buf),
                "the input field %s went non-finite (at t = %g)",
                fields_[f].c_str(), double(worstTime_[f])
            );
        }
        msgs.append(buf);
    }
    return msgs;
}

// ************************************************************************* //
