/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "spatialHash.H"
#include "error.H"

#include <cmath>

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

namespace
{

//- The bits of a 5-bit number spread to every third bit (Morton order)
constexpr std::uint32_t spread5(const std::uint32_t v)
{
    return (v & 1) | (v & 2) << 2 | (v & 4) << 4 | (v & 8) << 6
      | (v & 16) << 8;
}

constexpr std::uint32_t spreadTable[32] =
{
    spread5(0), spread5(1), spread5(2), spread5(3), spread5(4), spread5(5),
    spread5(6), spread5(7), spread5(8), spread5(9), spread5(10), spread5(11),
    spread5(12), spread5(13), spread5(14), spread5(15), spread5(16),
    spread5(17), spread5(18), spread5(19), spread5(20), spread5(21),
    spread5(22), spread5(23), spread5(24), spread5(25), spread5(26),
    spread5(27), spread5(28), spread5(29), spread5(30), spread5(31)
};

} // End anonymous namespace


inline std::uint64_t Foam::spatialHash::bucket
(
    const std::int64_t i,
    const std::int64_t j,
    const std::int64_t k
) const
{
    // Blocks of 2^bits cells per axis, their cells in Morton order in
    // consecutive buckets: neighbour cells lie near each other in memory at
    // every scale up to the block, so a scan over the buckets in order
    // finds its neighbours' points in the caches.  The blocks are hashed
    // to slots (large odd multipliers; the top bits of the product are the
    // best mixed).
    const std::int64_t low = (std::int64_t(1) << bits_) - 1;
    const std::uint64_t local =
        spreadTable[i & low] | spreadTable[j & low] << 1
      | spreadTable[k & low] << 2;
    const std::uint64_t v =
        std::uint64_t(i >> bits_)*0x9E3779B97F4A7C15ull
      ^ std::uint64_t(j >> bits_)*0xC2B2AE3D27D4EB4Full
      ^ std::uint64_t(k >> bits_)*0x165667B19E3779F9ull;
    return ((v ^ (v >> 29)) & mask_) << (3*bits_) | local;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::spatialHash::spatialHash(const scalar radius)
:
    h_(radius),
    bits_(2),
    mask_(0)
{
    if (!(radius > 0) || !std::isfinite(radius))
    {
        FatalErrorInFunction
            << "Radius " << radius << " is not a finite number > 0"
            << exit(FatalError);
    }
}


Foam::spatialHash::spatialHash(const UList<point>& x, const scalar radius)
:
    spatialHash(radius)
{
    build(x);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::spatialHash::build(const UList<point>& x)
{
    const label n = x.size();
    std::uint64_t nb = 64;
    while (nb < std::uint64_t(2*n)) nb <<= 1;
    // Blocks as large as leave at least 8 slots, from 4 to 32 cells a side
    // (4: the 27 neighbours of a cell fall in 27 different buckets)
    bits_ = 2;
    while (bits_ < 5 && (std::uint64_t(64) << (3*(bits_ + 1))) <= nb) ++bits_;
    mask_ = (nb >> (3*bits_)) - 1;

    // Cells (2^52 cells either way keeps floor exact and the cell a label)
    const scalar limit = 4.5e15;
    std::vector<std::uint32_t>& bucketOf = bucketOf_;
    bucketOf.resize(n);
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
        }
        std::int64_t c[3];
        cellOf(x[p], c);
        bucketOf[p] = std::uint32_t(bucket(c[0], c[1], c[2]));
        ++start_[bucketOf[p] + 1];
    }

    // Counting sort by bucket, with the positions in that order
    for (std::uint64_t b = 0; b < nb; ++b) start_[b + 1] += start_[b];
    std::vector<label>& fill = fill_;
    fill.assign(start_.begin(), start_.end() - 1);
    sorted_.resize(n);
    sx_.resize(n);
    for (label p = 0; p < n; ++p)
    {
        const label m = fill[bucketOf[p]]++;
        sorted_[m] = p;
        sx_[m] = x[p];
    }
}



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
    // The groups in bucket order, and per bucket its one group (mixed: a
    // bucket with points of several groups).  A run of one group skips a
    // bucket of that group without reading its points: inside a body
    // nothing is read but the bucket's group, so the search costs per
    // point next to nothing away from the contact surfaces.
    const label mixed = labelMin;
    std::vector<label>& sg = sg_;
    std::vector<label>& bg = bucketGroup_;
    sg.resize(grouped ? n : 0);
    bg.resize(grouped ? start_.size() - 1 : 0);
    for (label m = 0; grouped && m < n; ++m) sg[m] = group[sorted_[m]];
    for (std::size_t bk = 0; bk < bg.size(); ++bk)
    {
        const label e0 = start_[bk], e1 = start_[bk + 1];
        label g = e0 < e1 ? sg[e0] : mixed;
        for (label e = e0 + 1; e < e1 && g != mixed; ++e)
        {
            if (sg[e] != g) g = mixed;
        }
        bg[bk] = g;
    }

    // Room for one pair per point (no regrowth on the way for the usual
    // contact surfaces; more just grows)
    a.reserve(a.size() + n);
    b.reserve(b.size() + n);

    // Runs of entries of one cell [m0, m1): the 27 neighbour cells are
    // looked up once per run, not once per point (fewer random accesses)
    const scalar r2 = h_*h_;
    for (label m0 = 0, m1 = 0; m0 < n; m0 = m1)
    {
        std::int64_t ci[3], cj[3];
        cellOf(sx_[m0], ci);
        label runGroup = grouped ? sg[m0] : mixed;
        for (m1 = m0 + 1; m1 < n; ++m1)
        {
            cellOf(sx_[m1], cj);
            if (cj[0] != ci[0] || cj[1] != ci[1] || cj[2] != ci[2]) break;
            if (grouped && sg[m1] != runGroup) runGroup = mixed;
        }
        for (std::int64_t dk = -1; dk <= 1; ++dk)
        for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t di = -1; di <= 1; ++di)
        {
            const std::int64_t c0 = ci[0] + di, c1 = ci[1] + dj, c2 = ci[2] + dk;
            const std::uint64_t bk = bucket(c0, c1, c2);
            if (runGroup != mixed && bg[bk] == runGroup) continue;
            // Entries after m0 only; each pair once, from its first entry.
            // No cell comparison is needed: the 27 cells differ by less
            // than 4 in each direction, so their positions in their blocks
            // (and their buckets) differ, and a point of another cell that
            // shares this bucket lies a block side (4 cells, 3 radii) away
            // or more.
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
