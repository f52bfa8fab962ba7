/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "neighbourList.H"
#include "stateIO.H"
#include <algorithm>
#include <cmath>
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
    x0_(),
    cutoff0_(-1),
    slack_(),
    nBuilds_(0),
    nRelisted_(0),
    adjacency_(),
    cells_(),
    pairs_(),
    pairsBuild_(-1)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rbd::neighbourList::cellOf(const point& p, std::int64_t c[3]) const
{
    const scalar cell = cutoff0_ + skin_;
    c[0] = std::int64_t(std::floor(p.x()/cell));
    c[1] = std::int64_t(std::floor(p.y()/cell));
    c[2] = std::int64_t(std::floor(p.z()/cell));
}


void Foam::rbd::neighbourList::setCells()
{
    cells_.clear();
    forAll(x0_, b)
    {
        std::int64_t c[3];
        cellOf(x0_[b], c);
        cells_[cellKey(c[0], c[1], c[2])].push_back(b);
    }
}


void Foam::rbd::neighbourList::setAdjacency(const UList<labelPair>& pairs)
{
    adjacency_.setSize(x0_.size());
    for (DynamicList<label>& nbr : adjacency_)
    {
        nbr.clear();
    }
    for (const labelPair& pr : pairs)
    {
        adjacency_[pr.first()].append(pr.second());
        adjacency_[pr.second()].append(pr.first());
    }
    for (DynamicList<label>& nbr : adjacency_)
    {
        std::sort(nbr.begin(), nbr.end());
    }
}


void Foam::rbd::neighbourList::link(const label i, const label k)
{
    DynamicList<label>& nbr = adjacency_[i];
    label at = nbr.size();
    while (at > 0 && nbr[at - 1] > k)
    {
        --at;
    }
    if (at > 0 && nbr[at - 1] == k)
    {
        return;
    }
    nbr.append(k);
    for (label m = nbr.size() - 1; m > at; --m)
    {
        nbr[m] = nbr[m - 1];
    }
    nbr[at] = k;
}


void Foam::rbd::neighbourList::unlink(const label i, const label k)
{
    DynamicList<label>& nbr = adjacency_[i];
    label m = 0;
    while (m < nbr.size() && nbr[m] != k)
    {
        ++m;
    }
    for (; m + 1 < nbr.size(); ++m)
    {
        nbr[m] = nbr[m + 1];
    }
    if (m < nbr.size())
    {
        nbr.remove();
    }
}


void Foam::rbd::neighbourList::rebuild
(
    const UList<point>& x,
    const scalar cutoff
)
{
    x0_ = x;
    cutoff0_ = cutoff;
    setCells();
    // The pairs by the dense grid, then each body's neighbours in order
    DynamicList<labelPair> found;
    gridPairs(x0_, cutoff + skin_, found);
    setAdjacency(found);
    nRelisted_ += x0_.size();
}


void Foam::rbd::neighbourList::relist
(
    const label i,
    const point& xi,
    const bool inGrid
)
{
    std::int64_t c[3];
    if (inGrid)
    {
        cellOf(x0_[i], c);
        std::vector<label>& old = cells_[cellKey(c[0], c[1], c[2])];
        old.erase(std::find(old.begin(), old.end(), i));
        for (const label k : adjacency_[i])
        {
            unlink(k, i);
        }
        adjacency_[i].clear();
    }
    x0_[i] = xi;
    const scalar reach2 = sqr(cutoff0_ + skin_);
    cellOf(xi, c);
    for (int di = -1; di <= 1; ++di)
    {
        for (int dj = -1; dj <= 1; ++dj)
        {
            for (int dk = -1; dk <= 1; ++dk)
            {
                const auto it =
                    cells_.find(cellKey(c[0] + di, c[1] + dj, c[2] + dk));
                if (it == cells_.end())
                {
                    continue;
                }
                for (const label o : it->second)
                {
                    if (magSqr(x0_[o] - xi) < reach2)
                    {
                        link(i, o);
                        link(o, i);
                    }
                }
            }
        }
    }
    cells_[cellKey(c[0], c[1], c[2])].push_back(i);
    ++nRelisted_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::DynamicList<Foam::labelPair>&
Foam::rbd::neighbourList::pairs() const
{
    if (pairsBuild_ != nBuilds_)
    {
        pairs_.clear();
        forAll(adjacency_, i)
        {
            for (const label k : adjacency_[i])
            {
                if (k > i)
                {
                    pairs_.append(labelPair(i, k));
                }
            }
        }
        pairsBuild_ = nBuilds_;
    }
    return pairs_;
}


bool Foam::rbd::neighbourList::update
(
    const UList<point>& x,
    const scalar cutoff
)
{
    const label n0 = x0_.size();
    if (x.size() < n0 || cutoff != cutoff0_)
    {
        rebuild(x, cutoff);
        slack_.setSize(x.size());
        slack_ = 0.5*skin_;
        ++nBuilds_;
        return true;
    }

    // Bodies beyond skin/2 from their snapshots, and new ones, are listed
    // again in index order (the list does not depend on that order)
    std::vector<label> relisted;
    slack_.setSize(x.size());
    for (label i = 0; i < n0; ++i)
    {
        const scalar d2 = magSqr(x[i] - x0_[i]);
        if (d2 > sqr(0.5*skin_))
        {
            relisted.push_back(i);
            slack_[i] = 0.5*skin_;
        }
        else
        {
            slack_[i] = 0.5*skin_ - Foam::sqrt(d2);
        }
    }
    for (label i = n0; i < x.size(); ++i)
    {
        slack_[i] = 0.5*skin_;
    }
    if (relisted.empty() && x.size() == n0)
    {
        return false;
    }
    x0_.setSize(x.size());
    adjacency_.setSize(x.size());
    for (const label i : relisted)
    {
        relist(i, x[i], true);
    }
    for (label i = n0; i < x.size(); ++i)
    {
        adjacency_[i].clear();
        relist(i, x[i], false);
    }
    ++nBuilds_;
    return true;
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
    out.putList(pairs()).putList(x0_);
    out.putList(slack_);
    out.put(cutoff0_).put(nBuilds_).put(nRelisted_);
}


void Foam::rbd::neighbourList::readState(stateReader& in)
{
    DynamicList<labelPair> pairs;
    in.getList(pairs);
    List<point> x0;
    in.getList(x0);
    x0_ = x0;
    List<scalar> slack;
    in.getList(slack);
    slack_ = slack;
    in.get(cutoff0_).get(nBuilds_).get(nRelisted_);

    // The neighbours and the grid of the snapshots, as they were
    for (const labelPair& pr : pairs)
    {
        if
        (
            pr.first() < 0 || pr.first() >= pr.second()
         || pr.second() >= x0_.size()
        )
        {
            FatalErrorInFunction
                << "The checkpoint " << in.name().c_str() << " lists the "
                << "pair (" << pr.first() << ' ' << pr.second() << ") of "
                << x0_.size() << " pellets: it is damaged." << nl
                << "    Delete it and run without -resume." << exit(FatalError);
        }
    }
    setAdjacency(pairs);
    if (cutoff0_ >= 0)
    {
        setCells();
    }
    else
    {
        cells_.clear();
    }
    pairsBuild_ = -1;
}


// ************************************************************************* //
