/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "spatialHash.H"
#include "error.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

inline std::uint64_t Foam::spatialHash::bucket
(
    const std::int64_t i,
    const std::int64_t j,
    const std::int64_t k
) const
{
    // Bricks of 4 x 4 x 4 cells hashed to slots of 64 consecutive buckets:
    // a cell's neighbours mostly share its brick, so their points lie near
    // each other in memory.  Large odd multipliers spread the bricks; the
    // top bits of the product are the best mixed.
    const std::uint64_t local =
        std::uint64_t(i & 3) | std::uint64_t(j & 3) << 2
      | std::uint64_t(k & 3) << 4;
    const std::uint64_t v =
        std::uint64_t(i >> 2)*0x9E3779B97F4A7C15ull
      ^ std::uint64_t(j >> 2)*0xC2B2AE3D27D4EB4Full
      ^ std::uint64_t(k >> 2)*0x165667B19E3779F9ull;
    return ((v ^ (v >> 29)) & mask_) << 6 | local;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::spatialHash::spatialHash(const UList<point>& x, const scalar radius)
:
    h_(radius),
    mask_(0)
{
    if (!(radius > 0) || !std::isfinite(radius))
    {
        FatalErrorInFunction
            << "Radius " << radius << " is not a finite number > 0"
            << exit(FatalError);
    }
    const label n = x.size();
    std::uint64_t nb = 64;
    while (nb < std::uint64_t(2*n)) nb <<= 1;
    mask_ = nb/64 - 1;

    // Cells (2^52 cells either way keeps floor exact and the cell a label)
    const scalar limit = 4.5e15;
    std::vector<std::int64_t> cell(3*n);
    std::vector<std::uint64_t> bucketOf(n);
    start_.assign(nb + 1, 0);
    for (label p = 0; p < n; ++p)
    {
        for (direction d = 0; d < 3; ++d)
        {
            const scalar c = std::floor(x[p][d]/h_);
            if (!(std::abs(c) < limit))
            {
                FatalErrorInFunction
                    << "Point " << p << " at " << x[p] << " is not finite or"
                    << " lies more than " << limit << " radii (" << h_
                    << ") from the origin" << exit(FatalError);
            }
            cell[3*p + d] = std::int64_t(c);
        }
        bucketOf[p] = bucket(cell[3*p], cell[3*p + 1], cell[3*p + 2]);
        ++start_[bucketOf[p] + 1];
    }

    // Counting sort by bucket, with the positions and cells in that order
    for (std::uint64_t b = 0; b < nb; ++b) start_[b + 1] += start_[b];
    std::vector<label> fill(start_.begin(), start_.end() - 1);
    sorted_.resize(n);
    sx_.resize(n);
    sc_.resize(3*n);
    for (label p = 0; p < n; ++p)
    {
        const label m = fill[bucketOf[p]]++;
        sorted_[m] = p;
        sx_[m] = x[p];
        for (direction d = 0; d < 3; ++d) sc_[3*m + d] = cell[3*p + d];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::spatialHash::pairs
(
    const labelUList& group,
    DynamicList<label>& a,
    DynamicList<label>& b
) const
{
    const label n = sorted_.size();
    const bool grouped = !group.empty();
    if (grouped && group.size() != n)
    {
        FatalErrorInFunction
            << group.size() << " groups for " << n << " points"
            << exit(FatalError);
    }
    // The groups in bucket order
    std::vector<label> sg(grouped ? n : 0);
    for (label m = 0; grouped && m < n; ++m) sg[m] = group[sorted_[m]];

    // Room for one pair per point (no regrowth on the way for the usual
    // contact surfaces; more just grows)
    a.reserve(a.size() + n);
    b.reserve(b.size() + n);

    // Runs of entries of one cell [m0, m1): the 27 neighbour cells are
    // looked up once per run, not once per point (fewer random accesses)
    const scalar r2 = h_*h_;
    for (label m0 = 0, m1 = 0; m0 < n; m0 = m1)
    {
        const std::int64_t* ci = &sc_[3*m0];
        m1 = m0 + 1;
        while
        (
            m1 < n && sc_[3*m1] == ci[0] && sc_[3*m1 + 1] == ci[1]
         && sc_[3*m1 + 2] == ci[2]
        )
        {
            ++m1;
        }
        for (std::int64_t dk = -1; dk <= 1; ++dk)
        for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t di = -1; di <= 1; ++di)
        {
            const std::int64_t c0 = ci[0] + di, c1 = ci[1] + dj, c2 = ci[2] + dk;
            const std::uint64_t bk = bucket(c0, c1, c2);
            // Entries after m0 only; each pair once, from its first entry.
            // No cell comparison is needed: the 27 cells differ by less
            // than 4 in each direction, so they fall in 27 different
            // buckets of their bricks, and a point of another cell that
            // shares this bucket lies 4 cells (3 radii) away or more.
            for (label q = max(start_[bk], m0 + 1); q < start_[bk + 1]; ++q)
            {
                const point& xq = sx_[q];
                for (label m = m0; m < m1 && m < q; ++m)
                {
                    if (grouped && sg[m] == sg[q]) continue;
                    if (magSqr(xq - sx_[m]) >= r2) continue;
                    const label i = sorted_[m], j = sorted_[q];
                    a.append(min(i, j));
                    b.append(max(i, j));
                }
            }
        }
    }
}


// ************************************************************************* //
