/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "lcpBodySpace.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::lcpBodySpace::lcpBodySpace(const lcpFactors& factors)
:
    factors_(factors),
    Gt_(factors.G.transpose())
{
    Gt_.makeCompressed();
    const label d = Gt_.rows();
    const label n = Gt_.cols();
    const sparseMatrix GtG(Gt_*factors_.G);
    std::vector<Eigen::Triplet<double>> pattern;
    for (label j = 0; j < d; ++j)
    {
        pattern.emplace_back(j, j, 1.0);
        for (sparseMatrix::InnerIterator it(GtG, j); it; ++it)
        {
            if (it.row() > j)
            {
                pattern.emplace_back(it.row(), j, 1.0);
            }
        }
    }
    K_.resize(d, d);
    K_.setFromTriplets(pattern.begin(), pattern.end());
    K_.makeCompressed();

    // Slot of (row, col) in K's compressed columns
    const int* outer = K_.outerIndexPtr();
    const int* inner = K_.innerIndexPtr();
    auto slot = [&](const label row, const label col)
    {
        return label
        (
            std::lower_bound(inner + outer[col], inner + outer[col + 1], row)
          - inner
        );
    };
    for (label j = 0; j < d; ++j)
    {
        diagonalSlots_.push_back(slot(j, j));
    }
    slotStart_.assign(n + 1, 0);
    const int* gOuter = Gt_.outerIndexPtr();
    const int* gInner = Gt_.innerIndexPtr();
    for (label a = 0; a < n; ++a)
    {
        slotStart_[a] = slots_.size();
        for (label p = gOuter[a]; p < gOuter[a + 1]; ++p)
        {
            for (label q = gOuter[a]; q < gOuter[a + 1]; ++q)
            {
                if (gInner[p] >= gInner[q])
                {
                    slots_.push_back(slot(gInner[p], gInner[q]));
                    pairs_.emplace_back(p, q);
                }
            }
        }
    }
    slotStart_[n] = slots_.size();
    ldlt_.analyzePattern(K_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::rbd::lcpBodySpace::pays
(
    const sparseMatrix& A,
    const lcpFactors& factors
)
{
    return
        factors.valid() && factors.G.rows() == A.rows()
     && factors.G.cols() < A.rows();
}


Eigen::VectorXd Foam::rbd::lcpBodySpace::product
(
    const Eigen::VectorXd& x
) const
{
    return factors_.G*Eigen::VectorXd(Gt_*x) + factors_.s.cwiseProduct(x);
}


bool Foam::rbd::lcpBodySpace::factorise(const Eigen::VectorXd& Einv)
{
    Einv_ = Einv;
    if (!Einv_.allFinite())
    {
        return false;
    }
    double* k = K_.valuePtr();
    std::fill(k, k + K_.nonZeros(), 0.0);
    for (const label slot : diagonalSlots_)
    {
        k[slot] = 1;
    }
    const double* g = Gt_.valuePtr();
    for (label a = 0; a + 1 < label(slotStart_.size()); ++a)
    {
        const double e = Einv_(a);
        if (e == 0)
        {
            continue;
        }
        for (label i = slotStart_[a]; i < slotStart_[a + 1]; ++i)
        {
            k[slots_[i]] += e*g[pairs_[i].first]*g[pairs_[i].second];
        }
    }
    ldlt_.factorize(K_);
    return ldlt_.info() == Eigen::Success;
}


Eigen::VectorXd Foam::rbd::lcpBodySpace::apply(const Eigen::VectorXd& r) const
{
    const Eigen::VectorXd Er(Einv_.cwiseProduct(r));
    const Eigen::VectorXd y(ldlt_.solve(Gt_*Er));
    return Er - Einv_.cwiseProduct(factors_.G*y);
}


// ************************************************************************* //
