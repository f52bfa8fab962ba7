/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "orderingCache.H"

#include <Eigen/OrderingMethods>

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::orderingCache::orderingCache(const label capacity)
:
    capacity_(Foam::max(capacity, label(1))),
    entries_(),
    hits_(0),
    lookups_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::rbd::orderingCache::permutation&
Foam::rbd::orderingCache::order(const Eigen::SparseMatrix<double>& A)
{
    if (!A.isCompressed())
    {
        Eigen::SparseMatrix<double> compressed(A);
        compressed.makeCompressed();
        return order(compressed);
    }

    ++lookups_;

    const int n = A.cols();
    const int nnz = A.nonZeros();
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();

    for (auto it = entries_.begin(); it != entries_.end(); ++it)
    {
        if
        (
            int(it->outer.size()) == n + 1
         && int(it->inner.size()) == nnz
         && std::equal(it->outer.begin(), it->outer.end(), outer)
         && std::equal(it->inner.begin(), it->inner.end(), inner)
        )
        {
            ++hits_;
            entries_.splice(entries_.begin(), entries_, it);
            return entries_.front().order;
        }
    }

    entries_.emplace_front();
    entry& e = entries_.front();
    Eigen::AMDOrdering<int>()(A, e.order);
    e.outer.assign(outer, outer + n + 1);
    e.inner.assign(inner, inner + nnz);
    if (label(entries_.size()) > capacity_)
    {
        entries_.pop_back();
    }
    return e.order;
}


// ************************************************************************* //
