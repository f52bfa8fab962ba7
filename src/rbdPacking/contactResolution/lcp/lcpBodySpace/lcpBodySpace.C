/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "lcpBodySpace.H"

#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    //- M^T v for a column-major M: one dot product per column, summed in
    //  the order of the column's entries, as a column-major M^T v scatters
    //  them (the same sums bit for bit, fewer stores). By hand, serial:
    //  Eigen's M.transpose()*v (a row-major product) spreads itself over
    //  Eigen::nbThreads() threads above 20 000 nonzeros, inside a solve
    //  that is otherwise serial; what that would cost or save was not
    //  measured
    Eigen::VectorXd columnDots
    (
        const Eigen::SparseMatrix<double>& M,
        const Eigen::VectorXd& v
    )
    {
        const Foam::label nCols = M.cols();
        Eigen::VectorXd r(nCols);
        const int* outer = M.outerIndexPtr();
        const int* inner = M.innerIndexPtr();
        const double* value = M.valuePtr();
        const double* x = v.data();
        for (Foam::label j = 0; j < nCols; ++j)
        {
            double t = 0;
            for (int p = outer[j]; p < outer[j + 1]; ++p)
            {
                t += value[p]*x[inner[p]];
            }
            r(j) = t;
        }
        return r;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::lcpBodySpace::lcpBodySpace(const lcpFactors& factors)
:
    factors_(factors),
    Gt_(factors.G.transpose())
{
    Gt_.makeCompressed();
    const label d = Gt_.rows();
    const label n = Gt_.cols();

    // The pattern of K (lower triangle, diagonal included), each stored
    // value numbered: value v of K holds v + 1
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
    sparseMatrix K(d, d);
    K.setFromTriplets(pattern.begin(), pattern.end());
    K.makeCompressed();
    for (label v = 0; v < label(K.nonZeros()); ++v)
    {
        K.valuePtr()[v] = v + 1;
    }

    // AMD ordering of K's full pattern and the permuted upper triangle,
    // made as SimplicialLDLT<AMDOrdering> makes them (ordering(),
    // factorize()): the same ordering, the same storage order of the
    // entries, so the factorisation below does the same arithmetic
    {
        sparseMatrix C;
        C = K.selfadjointView<Eigen::Lower>();
        Eigen::AMDOrdering<int> amd;
        amd(C, Pinv_);
    }
    P_ = Pinv_.inverse();
    Kp_.resize(d, d);
    Kp_.selfadjointView<Eigen::Upper>() =
        K.selfadjointView<Eigen::Lower>().twistedBy(P_);

    // Where each value of K went in Kp_
    std::vector<label> toKp(K.nonZeros(), -1);
    for (label v = 0; v < label(Kp_.nonZeros()); ++v)
    {
        toKp[label(Kp_.valuePtr()[v]) - 1] = v;
    }

    // Slot of (row, col) of K (lower: row >= col) in Kp_
    const int* outer = K.outerIndexPtr();
    const int* inner = K.innerIndexPtr();
    auto slot = [&](const label row, const label col)
    {
        return toKp
        [
            std::lower_bound(inner + outer[col], inner + outer[col + 1], row)
          - inner
        ];
    };
    for (label j = 0; j < d; ++j)
    {
        diagonalSlots_.push_back(slot(j, j));
    }
    // Column a of G^T is sorted by row: p >= q in storage is row p >=
    // row q
    slotStart_.assign(n + 1, 0);
    const int* gOuter = Gt_.outerIndexPtr();
    const int* gInner = Gt_.innerIndexPtr();
    for (label a = 0; a < n; ++a)
    {
        slotStart_[a] = slots_.size();
        for (label p = gOuter[a]; p < gOuter[a + 1]; ++p)
        {
            for (label q = gOuter[a]; q <= p; ++q)
            {
                slots_.push_back(slot(gInner[p], gInner[q]));
            }
        }
    }
    slotStart_[n] = slots_.size();
    ldlt_.analyzePattern(Kp_);
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
    // G^T x: the columns of G; G y: the columns of G^T (rows of G)
    return
        columnDots(Gt_, columnDots(factors_.G, x))
      + factors_.s.cwiseProduct(x);
}


bool Foam::rbd::lcpBodySpace::factorise(const Eigen::VectorXd& Einv)
{
    Einv_ = Einv;
    if (!Einv_.allFinite())
    {
        return false;
    }
    double* k = Kp_.valuePtr();
    std::fill(k, k + Kp_.nonZeros(), 0.0);
    for (const label slot : diagonalSlots_)
    {
        k[slot] = 1;
    }
    const double* g = Gt_.valuePtr();
    const int* gOuter = Gt_.outerIndexPtr();
    for (label a = 0; a + 1 < label(slotStart_.size()); ++a)
    {
        const double e = Einv_(a);
        if (e == 0)
        {
            continue;
        }
        const label* s = slots_.data() + slotStart_[a];
        for (label p = gOuter[a]; p < gOuter[a + 1]; ++p)
        {
            const double eg = e*g[p];
            for (label q = gOuter[a]; q <= p; ++q)
            {
                k[*s++] += eg*g[q];
            }
        }
    }
    ldlt_.factorize(Kp_);
    return ldlt_.info() == Eigen::Success;
}


Eigen::VectorXd Foam::rbd::lcpBodySpace::apply(const Eigen::VectorXd& r) const
{
    const Eigen::VectorXd Er(Einv_.cwiseProduct(r));
    // As SimplicialLDLT<AMDOrdering>::solve: ordered, solved, ordered back
    const Eigen::VectorXd rp(P_*columnDots(factors_.G, Er));
    const Eigen::VectorXd y(Pinv_*ldlt_.solve(rp));
    return Er - Einv_.cwiseProduct(columnDots(Gt_, y));
}


// ************************************************************************* //
