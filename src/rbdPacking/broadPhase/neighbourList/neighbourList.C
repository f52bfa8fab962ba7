/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "neighbourList.H"
#include "stateIO.H"
#include <algorithm>
#include <cstdint>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    // 21 bits per direction, offset so that negative cells pack too
    constexpr std::int64_t cellBits = 21;
    constexpr std::int64_t cellOffset = std::int64_t(1) << (cellBits - 1);

    inline std::int64_t cellKey(std::int64_t i, std::int64_t j, std::int64_t k)
    {
        return
            ((i + cellOffset) << (2*cellBits))
          | ((j + cellOffset) << cellBits)
          | (k + cellOffset);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::neighbourList::neighbourList(const scalar skin)
:
    skin_(skin),
    pairs_(),
    x0_(),
    cutoff0_(-1),
    maxMoved_(0),
    nBuilds_(0),
    adjacency_(),
    adjacencyBuild_(-1)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::labelListList& Foam::rbd::neighbourList::adjacency() const
{
    if (adjacencyBuild_ != nBuilds_)
    {
        labelList nNbr(x0_.size(), 0);
        for (const labelPair& pr : pairs_)
        {
            ++nNbr[pr.first()];
            ++nNbr[pr.second()];
        }
        adjacency_.setSize(x0_.size());
        forAll(adjacency_, i)
        {
            adjacency_[i].setSize(nNbr[i]);
            nNbr[i] = 0;
        }
        for (const labelPair& pr : pairs_)
        {
            const label i = pr.first();
            const label k = pr.second();
            adjacency_[i][nNbr[i]++] = k;
            adjacency_[k][nNbr[k]++] = i;
        }
        adjacencyBuild_ = nBuilds_;
    }
    return adjacency_;
}


bool Foam::rbd::neighbourList::update
(
    const UList<point>& x,
    const scalar cutoff
)
{
    bool rebuild = (x.size() != x0_.size()) || (cutoff != cutoff0_);

    scalar moved2 = 0;
    if (!rebuild)
    {
        forAll(x, i)
        {
            moved2 = max(moved2, magSqr(x[i] - x0_[i]));
        }
        rebuild = moved2 > sqr(0.5*skin_);
    }

    if (rebuild)
    {
        gridPairs(x, cutoff + skin_, pairs_);
        x0_ = x;
        cutoff0_ = cutoff;
        moved2 = 0;
        ++nBuilds_;
    }
    maxMoved_ = Foam::sqrt(moved2);

    return rebuild;
}


void Foam::rbd::neighbourList::gridPairs
(
    const UList<point>& x,
    const scalar cutoff,
    DynamicList<labelPair>& pairs
)
{
    pairs.clear();

    const label n = x.size();
    if (n < 2)
    {
        return;
    }

    const scalar cell = cutoff;
    const scalar cutoff2 = sqr(cutoff);

    // Cells of size cutoff: a pair closer than cutoff lies in one cell or
    // in two neighbouring ones
    std::vector<std::int64_t> ci(n), cj(n), ck(n);
    std::int64_t lo[3], hi[3];
    for (label b = 0; b < n; ++b)
    {
        ci[b] = std::int64_t(std::floor(x[b].x()/cell));
        cj[b] = std::int64_t(std::floor(x[b].y()/cell));
        ck[b] = std::int64_t(std::floor(x[b].z()/cell));
        const std::int64_t c[3] = {ci[b], cj[b], ck[b]};
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = b ? std::min(lo[d], c[d]) : c[d];
            hi[d] = b ? std::max(hi[d], c[d]) : c[d];
        }
    }

    // A dense grid over the bodies' box (padded by one cell, so that the
    // 27 neighbours of a cell are in it) where it is small, as in a tube;
    // else (a pellet thrown far out) the cells sorted by key
    const std::int64_t ni = hi[0] - lo[0] + 3;
    const std::int64_t nj = hi[1] - lo[1] + 3;
    const std::int64_t nk = hi[2] - lo[2] + 3;
    if (double(ni)*nj*nk <= double(maxDenseCellsPerBody*n + 1000))
    {
        denseGridPairs(x, cutoff2, ci, cj, ck, lo, ni, nj, nk, pairs);
        return;
    }

    std::vector<std::pair<std::int64_t, label>> keys(n);
    for (label b = 0; b < n; ++b)
    {
        keys[b] = {cellKey(ci[b], cj[b], ck[b]), b};
    }
    std::sort(keys.begin(), keys.end());

    for (label b = 0; b < n; ++b)
    {
        for (int di = -1; di <= 1; ++di)
        {
            for (int dj = -1; dj <= 1; ++dj)
            {
                for (int dk = -1; dk <= 1; ++dk)
                {
                    const std::int64_t key =
                        cellKey(ci[b] + di, cj[b] + dj, ck[b] + dk);

                    auto it = std::lower_bound
                    (
                        keys.begin(), keys.end(),
                        std::make_pair(key, label(-1))
                    );

                    for (; it != keys.end() && it->first == key; ++it)
                    {
                        const label o = it->second;
                        if (o > b && magSqr(x[o] - x[b]) < cutoff2)
                        {
                            pairs.append(labelPair(b, o));
                        }
                    }
                }
            }
        }
    }
}


void Foam::rbd::neighbourList::denseGridPairs
(
    const UList<point>& x,
    const scalar cutoff2,
    const std::vector<std::int64_t>& ci,
    const std::vector<std::int64_t>& cj,
    const std::vector<std::int64_t>& ck,
    const std::int64_t lo[3],
    const std::int64_t ni,
    const std::int64_t nj,
    const std::int64_t nk,
    DynamicList<labelPair>& pairs
)
{
    const label n = x.size();

    // Cell of each body in the padded grid, and the bodies of each cell
    // in ascending order (a counting sort, stable in the body index): the
    // pairs come out in the order of the sorted-key search, body by body,
    // neighbour cell by neighbour cell, so the contact list and with it
    // the packing are the same bit for bit
    const auto cellOf = [&](const label b)
    {
        return
            ((ci[b] - lo[0] + 1)*nj + (cj[b] - lo[1] + 1))*nk
          + (ck[b] - lo[2] + 1);
    };
    std::vector<label> start(ni*nj*nk + 1, 0);
    std::vector<std::int64_t> cellOfBody(n);
    for (label b = 0; b < n; ++b)
    {
        cellOfBody[b] = cellOf(b);
        ++start[cellOfBody[b] + 1];
    }
    for (std::size_t c = 1; c < start.size(); ++c)
    {
        start[c] += start[c - 1];
    }
    std::vector<label> members(n), fill(start.begin(), start.end() - 1);
    for (label b = 0; b < n; ++b)
    {
        members[fill[cellOfBody[b]]++] = b;
    }

    for (label b = 0; b < n; ++b)
    {
        const std::int64_t c0 = cellOfBody[b];
        for (int di = -1; di <= 1; ++di)
        {
            for (int dj = -1; dj <= 1; ++dj)
            {
                for (int dk = -1; dk <= 1; ++dk)
                {
                    const std::int64_t c = c0 + (di*nj + dj)*nk + dk;
                    for (label m = start[c]; m < start[c + 1]; ++m)
                    {
                        const label o = members[m];
                        if (o > b && magSqr(x[o] - x[b]) < cutoff2)
                        {
                            pairs.append(labelPair(b, o));
                        }
                    }
                }
            }
        }
    }
}


void Foam::rbd::neighbourList::bruteForce
(
    const UList<point>& x,
    const scalar cutoff,
    DynamicList<labelPair>& pairs
)
{
    pairs.clear();
    const scalar cutoff2 = sqr(cutoff);

    forAll(x, i)
    {
        for (label k = i + 1; k < x.size(); ++k)
        {
            if (magSqr(x[k] - x[i]) < cutoff2)
            {
                pairs.append(labelPair(i, k));
            }
        }
    }
}


void Foam::rbd::neighbourList::writeState(stateWriter& out) const
{
    out.putList(pairs_).putList(x0_);
    out.put(cutoff0_).put(maxMoved_).put(nBuilds_);
}


void Foam::rbd::neighbourList::readState(stateReader& in)
{
    in.getList(pairs_);
    List<point> x0;
    in.getList(x0);
    x0_ = x0;
    in.get(cutoff0_).get(maxMoved_).get(nBuilds_);
    adjacencyBuild_ = -1;
}


// ************************************************************************* //
