/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "coupledPressureSystem.H"
#include "mpmParallel.H"
#include "gasB2B1Operator.H"
#include "PstreamReduceOps.H"
#include <cmath>
#include <numeric>
#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coupledPressureSystem::beginSolid(label nNodes)
{
    if (label(rowOf_.size()) != 3*nNodes) rowOf_.assign(3*nNodes, -1);
    for (size_t k = 0; k < rowNode_.size(); ++k)
    {
        rowOf_[3*rowNode_[k] + rowDir_[k]] = -1;
    }
    rowNode_.clear();
    rowDir_.clear();
    tRow_.clear();
    tCol_.clear();
    tVal_.clear();
}


void Foam::coupledPressureSystem::addFaceNode
(
    label node,
    label d,
    label l,
    label r,
    double w
)
{
    label& row = rowOf_[3*node + d];
    if (row < 0)
    {
        row = label(rowNode_.size());
        rowNode_.push_back(node);
        rowDir_.push_back(d);
    }
    if (l >= 0)
    {
        tRow_.push_back(row); tCol_.push_back(l); tVal_.push_back(-w);
    }
    if (r >= 0)
    {
        tRow_.push_back(row); tCol_.push_back(r); tVal_.push_back(w);
    }
}


void Foam::coupledPressureSystem::endSolid(const UList<scalar>& nodeMass)
{
    // Compress by row, summing entries of one (row, cell)
    const label nR = nRows();
    const label nT = label(tRow_.size());
    std::vector<label> order(nT);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort
    (
        order.begin(), order.end(),
        [&](label a, label b)
        {
            return tRow_[a] < tRow_[b]
                || (tRow_[a] == tRow_[b] && tCol_[a] < tCol_[b]);
        }
    );
    rowStart_.assign(nR + 1, 0);
    col_.clear();
    val_.clear();
    label prevRow = -1, prevCol = -1;
    for (const label t : order)
    {
        if (tRow_[t] == prevRow && tCol_[t] == prevCol)
        {
            val_.back() += tVal_[t];
            continue;
        }
        prevRow = tRow_[t];
        prevCol = tCol_[t];
        col_.push_back(tCol_[t]);
        val_.push_back(tVal_[t]);
        ++rowStart_[prevRow + 1];
    }
    for (label k = 0; k < nR; ++k) rowStart_[k + 1] += rowStart_[k];

    invMass_.resize(nR);
    for (label k = 0; k < nR; ++k)
    {
        invMass_[k] = 1.0/nodeMass[rowNode_[k]];
        // Jacobi: the diagonal of T^T M^-1 T
        for (label e = rowStart_[k]; e < rowStart_[k + 1]; ++e)
        {
            gas.diag[col_[e]] += invMass_[k]*val_[e]*val_[e];
        }
    }
}


void Foam::coupledPressureSystem::addSolidSource
(
    const UList<vector>& v,
    double dt
)
{
    const label nR = nRows();
    for (label k = 0; k < nR; ++k)
    {
        const double vk = v[rowNode_[k]][rowDir_[k]];
        for (label e = rowStart_[k]; e < rowStart_[k + 1]; ++e)
        {
            gas.source[col_[e]] += val_[e]*vk/dt;
        }
    }
}


void Foam::coupledPressureSystem::applyT
(
    const std::vector<double>& x,
    std::vector<double>& y
) const
{
    const label nR = nRows();
    y.resize(nR);
    for (label k = 0; k < nR; ++k)
    {
        double s = 0;
        for (label e = rowStart_[k]; e < rowStart_[k + 1]; ++e)
        {
            s += val_[e]*x[col_[e]];
        }
        y[k] = s;
    }
    if (par)
    {
        // Each rank's part holds its cells' columns: the sum over the
        // ranks holding the node
        rowsAll_.setSize(par->view().nVertices());
        rowsAll_ = Zero;
        for (label k = 0; k < nR; ++k) rowsAll_[rowNode_[k]][rowDir_[k]] = y[k];
        par->sumShared(rowsAll_);
        for (label k = 0; k < nR; ++k) y[k] = rowsAll_[rowNode_[k]][rowDir_[k]];
    }
}


void Foam::coupledPressureSystem::addProduct
(
    const std::vector<double>& x,
    std::vector<double>& y
) const
{
    // The gas's LDU product took its diag, which holds the solid's Jacobi
    // diagonal too: take that back out, then add T^T M^-1 T x exactly
    const label nR = nRows();
    if (nR == 0 && !par) return;
    applyT(x, u_);
    for (label k = 0; k < nR; ++k)
    {
        const double uk = u_[k]*invMass_[k];
        for (label e = rowStart_[k]; e < rowStart_[k + 1]; ++e)
        {
            const label c = col_[e];
            y[c] += val_[e]*(uk - invMass_[k]*val_[e]*x[c]);
        }
    }
}


// ************************************************************************* //
