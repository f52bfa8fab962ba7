/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "updatableCholesky.H"
#include "error.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::updatableCholesky::updatableCholesky(const label capacity)
:
    L_(capacity, capacity),
    size_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::rbd::updatableCholesky::append
(
    const Eigen::Ref<const Eigen::VectorXd>& c,
    const scalar s,
    const scalar minPivot2
)
{
    const label m = size_;
    if (m >= L_.rows() || c.size() != m)
    {
        FatalErrorInFunction
            << "cannot grow a factor of order " << m << " (capacity "
            << label(L_.rows()) << ") by a column of size "
            << label(c.size()) << exit(FatalError);
    }

    // l = L^-1 c, stored as the new row m
    Eigen::VectorXd l = c;
    if (m > 0)
    {
        L_.topLeftCorner(m, m).triangularView<Eigen::Lower>()
            .solveInPlace(l);
    }
    const scalar p2 = s - l.squaredNorm();
    if (!(p2 > minPivot2))
    {
        return false;
    }

    L_.row(m).head(m) = l.transpose();
    L_.col(m).head(m).setZero();
    L_(m, m) = std::sqrt(p2);
    ++size_;
    return true;
}


void Foam::rbd::updatableCholesky::remove(const label k)
{
    const label m = size_;
    if (k < 0 || k >= m)
    {
        FatalErrorInFunction
            << "no row " << k << " in a factor of order " << m
            << exit(FatalError);
    }

    // The column below the removed pivot drives the rank-one update
    const label t = m - k - 1;
    Eigen::VectorXd x = L_.col(k).segment(k + 1, t);

    // Close the gap: rows k+1.. move up one, columns k+1.. left one
    for (label i = k; i < m - 1; ++i)
    {
        L_.row(i).head(k) = L_.row(i + 1).head(k);
        for (label j = k; j <= i; ++j)
        {
            L_(i, j) = L_(i + 1, j + 1);
        }
    }

    // Rank-one update of the trailing t x t block: T T^T + x x^T
    for (label i = 0; i < t; ++i)
    {
        const label ii = k + i;
        const scalar lii = L_(ii, ii);
        const scalar r = std::hypot(lii, x(i));
        const scalar cs = r/lii;
        const scalar sn = x(i)/lii;
        L_(ii, ii) = r;
        for (label j = i + 1; j < t; ++j)
        {
            const label jj = k + j;
            L_(jj, ii) = (L_(jj, ii) + sn*x(j))/cs;
            x(j) = cs*x(j) - sn*L_(jj, ii);
        }
    }

    --size_;
}


void Foam::rbd::updatableCholesky::solveInPlace
(
    Eigen::Ref<Eigen::VectorXd> x
) const
{
    if (size_ == 0)
    {
        return;
    }
    const auto Lm = L_.topLeftCorner(size_, size_);
    Lm.triangularView<Eigen::Lower>().solveInPlace(x);
    Lm.transpose().triangularView<Eigen::Upper>().solveInPlace(x);
}


// ************************************************************************* //
