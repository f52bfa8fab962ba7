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

    std::vector<std::int64_t> ci(n), cj(n), ck(n);
    std::vector<std::pair<std::int64_t, label>> keys(n);

    for (label b = 0; b < n; ++b)
    {
        ci[b] = std::int64_t(std::floor(x[b].x()/cell));
        cj[b] = std::int64_t(std::floor(x[b].y()/cell));
        ck[b] = std::int64_t(std::floor(x[b].z()/cell));
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
