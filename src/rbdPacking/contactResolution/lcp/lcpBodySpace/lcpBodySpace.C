/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "lcpBodySpace.H"
#include "error.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::lcpBodySpace::lcpBodySpace(const lcpFactors& factors)
:
    factors_(factors),
    nBodies_(factors.G.cols()/6)
{
    if (factors.G.cols() != 6*nBodies_)
    {
        FatalErrorInFunction
            << "G has " << label(factors.G.cols())
            << " columns, not 6 per body" << abort(FatalError);
    }
    analyse();
}


// * * * * * * * * * * * * * * Private Member Functions * * * * * * * * * * //

void Foam::rbd::lcpBodySpace::analyse()
{
    const label n = factors_.G.rows();
    const label nb = nBodies_;

    // Rows of G by bodies, in natural body numbering first
    const sparseMatrix Gt(factors_.G.transpose());
    rowStart_.assign(n + 1, 0);
    rowBody_.clear();
    rowG_.clear();
    for (label a = 0; a < n; ++a)
    {
        rowStart_[a] = rowBody_.size();
        for (sparseMatrix::InnerIterator it(Gt, a); it; ++it)
        {
            const label body = it.row()/6;
            const bool first = rowBody_.size() == size_t(rowStart_[a]);
            if (first || rowBody_.back() != body)
            {
                rowBody_.push_back(body);
                rowG_.push_back(bodyVector::Zero());
            }
            rowG_.back()(it.row() % 6) = it.value();
        }
    }
    rowStart_[n] = rowBody_.size();

    // The body graph (both triangles, diagonal included) and its AMD
    // ordering: body b is eliminated at place(b)
    std::vector<label> place(nb);
    {
        std::vector<Eigen::Triplet<double>> t;
        for (label b = 0; b < nb; ++b)
        {
            t.emplace_back(b, b, 1.0);
        }
        for (label a = 0; a < n; ++a)
        {
            for (label p = rowStart_[a]; p < rowStart_[a + 1]; ++p)
            {
                for (label q = rowStart_[a]; q < p; ++q)
                {
                    t.emplace_back(rowBody_[p], rowBody_[q], 1.0);
                    t.emplace_back(rowBody_[q], rowBody_[p], 1.0);
                }
            }
        }
        sparseMatrix C(nb, nb);
        C.setFromTriplets(t.begin(), t.end());
        C.makeCompressed();
        Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> Pinv;
        Eigen::AMDOrdering<int> amd;
        amd(C, Pinv);
        // Pinv maps a place to its body (as SimplicialLDLT reads it)
        for (label k = 0; k < nb; ++k)
        {
            place[Pinv.indices()(k)] = k;
        }
    }
    for (label& body : rowBody_)
    {
        body = place[body];
    }

    // Each place's neighbours after it, then the pattern of L by the
    // elimination tree: column j's rows are its later neighbours and the
    // rows of its children less j; its parent is its first row
    std::vector<std::vector<label>> later(nb);
    for (label a = 0; a < n; ++a)
    {
        for (label p = rowStart_[a]; p < rowStart_[a + 1]; ++p)
        {
            for (label q = rowStart_[a]; q < rowStart_[a + 1]; ++q)
            {
                if (rowBody_[p] > rowBody_[q])
                {
                    later[rowBody_[q]].push_back(rowBody_[p]);
                }
            }
        }
    }
    std::vector<std::vector<label>> children(nb);
    std::vector<std::vector<label>> rows(nb);
    for (label j = 0; j < nb; ++j)
    {
        std::vector<label>& r = rows[j];
        r = later[j];
        for (const label c : children[j])
        {
            for (const label i : rows[c])
            {
                if (i != j)
                {
                    r.push_back(i);
                }
            }
        }
        std::sort(r.begin(), r.end());
        r.erase(std::unique(r.begin(), r.end()), r.end());
        if (!r.empty())
        {
            children[r.front()].push_back(j);
        }
    }
    colStart_.assign(nb + 1, 0);
    colRows_.clear();
    for (label j = 0; j < nb; ++j)
    {
        colStart_[j] = colRows_.size();
        colRows_.insert(colRows_.end(), rows[j].begin(), rows[j].end());
    }
    colStart_[nb] = colRows_.size();

    // Block (i, k) of L, i > k: its index in offDiagonal_
    auto slot = [&](const label i, const label k)
    {
        const label* first = colRows_.data() + colStart_[k];
        const label* last = colRows_.data() + colStart_[k + 1];
        return label(std::lower_bound(first, last, i) - colRows_.data());
    };

    // Updates of the right-looking factorisation: column j takes
    // L_pj L_qj^T off block (p, q) for its rows p >= q (rows of a column
    // are rows of its later columns: the elimination tree's property)
    updateStart_.assign(nb + 1, 0);
    updates_.clear();
    for (label j = 0; j < nb; ++j)
    {
        updateStart_[j] = updates_.size();
        for (label p = colStart_[j]; p < colStart_[j + 1]; ++p)
        {
            for (label q = colStart_[j]; q <= p; ++q)
            {
                updates_.push_back
                (
                    p == q
                  ? -1 - colRows_[p]
                  : slot(colRows_[p], colRows_[q])
                );
            }
        }
    }
    updateStart_[nb] = updates_.size();

    // Where each row's pairs of bodies add to K
    rowPairStart_.assign(n + 1, 0);
    rowPairSlot_.clear();
    for (label a = 0; a < n; ++a)
    {
        rowPairStart_[a] = rowPairSlot_.size();
        for (label p = rowStart_[a]; p < rowStart_[a + 1]; ++p)
        {
            for (label q = rowStart_[a]; q < p; ++q)
            {
                const label bp = rowBody_[p];
                const label bq = rowBody_[q];
                rowPairSlot_.push_back
                (
                    bp > bq ? slot(bp, bq) : slot(bq, bp)
                );
            }
        }
    }
    rowPairStart_[n] = rowPairSlot_.size();

    diagonal_.resize(nb);
    offDiagonal_.resize(colRows_.size());
}


void Foam::rbd::lcpBodySpace::transposeProduct
(
    const Eigen::VectorXd& v,
    bodyVectorList& z
) const
{
    z.assign(nBodies_, bodyVector::Zero());
    const label n = rowStart_.size() - 1;
    for (label a = 0; a < n; ++a)
    {
        const double va = v(a);
        if (va == 0)
        {
            continue;
        }
        for (label p = rowStart_[a]; p < rowStart_[a + 1]; ++p)
        {
            z[rowBody_[p]] += va*rowG_[p];
        }
    }
}


Eigen::VectorXd Foam::rbd::lcpBodySpace::product
(
    const bodyVectorList& z
) const
{
    const label n = rowStart_.size() - 1;
    Eigen::VectorXd r(n);
    for (label a = 0; a < n; ++a)
    {
        double t = 0;
        for (label p = rowStart_[a]; p < rowStart_[a + 1]; ++p)
        {
            t += rowG_[p].dot(z[rowBody_[p]]);
        }
        r(a) = t;
    }
    return r;
}


void Foam::rbd::lcpBodySpace::assembleK()
{
    for (block& D : diagonal_)
    {
        D.setIdentity();
    }
    for (block& B : offDiagonal_)
    {
        B.setZero();
    }
    const label n = rowStart_.size() - 1;
    for (label a = 0; a < n; ++a)
    {
        const double e = Einv_(a);
        if (e == 0)
        {
            continue;
        }
        label pair = rowPairStart_[a];
        for (label p = rowStart_[a]; p < rowStart_[a + 1]; ++p)
        {
            const bodyVector eg(e*rowG_[p]);
            diagonal_[rowBody_[p]].noalias() += eg*rowG_[p].transpose();
            for (label q = rowStart_[a]; q < p; ++q)
            {
                // Block (later place, earlier place)
                block& K = offDiagonal_[rowPairSlot_[pair++]];
                if (rowBody_[p] > rowBody_[q])
                {
                    K.noalias() += eg*rowG_[q].transpose();
                }
                else
                {
                    K.noalias() += rowG_[q]*eg.transpose();
                }
            }
        }
    }
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
     && factors.G.cols() % 6 == 0
     && factors.G.cols() < A.rows();
}


Eigen::VectorXd Foam::rbd::lcpBodySpace::product
(
    const Eigen::VectorXd& x
) const
{
    bodyVectorList z;
    transposeProduct(x, z);
    return product(z) + factors_.s.cwiseProduct(x);
}


bool Foam::rbd::lcpBodySpace::factorise(const Eigen::VectorXd& Einv)
{
    Einv_ = Einv;
    if (!Einv_.allFinite())
    {
        return false;
    }

    assembleK();

    // Right-looking block Cholesky, in place
    for (label j = 0; j < nBodies_; ++j)
    {
        Eigen::LLT<block> llt(diagonal_[j]);
        if (llt.info() != Eigen::Success)
        {
            return false;
        }
        diagonal_[j] = llt.matrixL();
        const block& L = diagonal_[j];
        for (label p = colStart_[j]; p < colStart_[j + 1]; ++p)
        {
            // L_pj = K_pj L_jj^-T: each row of K_pj solved forward
            block& X = offDiagonal_[p];
            for (int c = 0; c < 6; ++c)
            {
                for (int k = 0; k < c; ++k)
                {
                    X.col(c) -= L(c, k)*X.col(k);
                }
                X.col(c) /= L(c, c);
            }
        }
        const label* u = updates_.data() + updateStart_[j];
        for (label p = colStart_[j]; p < colStart_[j + 1]; ++p)
        {
            for (label q = colStart_[j]; q <= p; ++q)
            {
                const label to = *u++;
                block& B = to < 0 ? diagonal_[-1 - to] : offDiagonal_[to];
                B.noalias() -= offDiagonal_[p]*offDiagonal_[q].transpose();
            }
        }
    }
    return true;
}


Eigen::VectorXd Foam::rbd::lcpBodySpace::apply(const Eigen::VectorXd& r) const
{
    const Eigen::VectorXd Er(Einv_.cwiseProduct(r));
    bodyVectorList y;
    transposeProduct(Er, y);

    // L L^T y = G^T E^-1 r: forward, then back
    for (label j = 0; j < nBodies_; ++j)
    {
        const block& L = diagonal_[j];
        bodyVector& yj = y[j];
        for (int c = 0; c < 6; ++c)
        {
            for (int k = 0; k < c; ++k)
            {
                yj(c) -= L(c, k)*yj(k);
            }
            yj(c) /= L(c, c);
        }
        for (label p = colStart_[j]; p < colStart_[j + 1]; ++p)
        {
            y[colRows_[p]].noalias() -= offDiagonal_[p]*yj;
        }
    }
    for (label j = nBodies_ - 1; j >= 0; --j)
    {
        bodyVector& yj = y[j];
        for (label p = colStart_[j]; p < colStart_[j + 1]; ++p)
        {
            yj.noalias() -= offDiagonal_[p].transpose()*y[colRows_[p]];
        }
        const block& L = diagonal_[j];
        for (int c = 5; c >= 0; --c)
        {
            for (int k = c + 1; k < 6; ++k)
            {
                yj(c) -= L(k, c)*yj(k);
            }
            yj(c) /= L(c, c);
        }
    }

    return Er - Einv_.cwiseProduct(product(y));
}


// ************************************************************************* //
