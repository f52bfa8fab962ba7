/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "lcpAssembly.H"
#include "lcpActiveSet.H"
#include <Eigen/Dense>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::lcpAssembly::lcpAssembly(const scalar compliance)
:
    compliance_(compliance),
    rowsI_(),
    rowsK_(),
    bodyRows_(),
    bodyColumn_(),
    slot_(),
    gTriplets_(),
    movingBodies_(0)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::lcpAssembly::assemble
(
    const UList<rigidBody>& bodies,
    const UList<contact>& contacts,
    const boolList& fixed,
    const std::vector<constraint>& dirs,
    Eigen::SparseMatrix<double>& A,
    Eigen::VectorXd& shift,
    lcpFactors& factors,
    const entries which
)
{
    if (label(bodyRows_.size()) < bodies.size())
    {
        bodyRows_.resize(bodies.size());
        bodyColumn_.resize(bodies.size(), -1);
    }

    const label n = dirs.size();
    const row zero{Zero, Zero, Zero, Zero};
    rowsI_.assign(n, zero);
    rowsK_.assign(n, zero);

    // Jacobian rows and the bodies' contact lists
    for (label a = 0; a < n; ++a)
    {
        const contact& c = contacts[dirs[a].first];
        const vector& u = dirs[a].second;
        const rigidBody& bi = bodies[c.i];
        const vector ri(c.p - bi.x());
        row& Ri = rowsI_[a];
        Ri.lin = u;
        Ri.ang = (ri ^ u);
        Ri.wLin = bi.invMass()*Ri.lin;
        Ri.wAng = bi.applyInvInertia(Ri.ang);

        if (c.k >= 0 && !fixed[c.k])
        {
            const rigidBody& bk = bodies[c.k];
            const vector rk(c.p - bk.x());
            row& Rk = rowsK_[a];
            Rk.lin = -u;
            Rk.ang = -(rk ^ u);
            Rk.wLin = bk.invMass()*Rk.lin;
            Rk.wAng = bk.applyInvInertia(Rk.ang);
        }
    }

    // Summed over the bodies two rows share: sparse, from each moving
    // body's list of the island's rows on it
    std::vector<label> touched;
    auto addRow = [&](const label body, const label a, const bool kSide)
    {
        if (body >= 0 && !fixed[body])
        {
            if (bodyRows_[body].empty())
            {
                touched.push_back(body);
            }
            bodyRows_[body].emplace_back(a, kSide);
        }
    };
    for (label a = 0; a < n; ++a)
    {
        const contact& c = contacts[dirs[a].first];
        addRow(c.i, a, false);
        addRow(c.k, a, true);
    }
    movingBodies_ = touched.size();

    // Fewer body columns (6 per moving body) than rows: the factors
    // pay (below)
    const bool factorsPay = 6*label(touched.size()) < n;
    if (which == entries::diagonalInBodySpace && factorsPay)
    {
        diagonal(contacts, fixed, dirs, A);
    }
    else
    {
        allEntries(contacts, fixed, dirs, A);
    }
    for (const label body : touched)
    {
        bodyRows_[body].clear();
    }

    // The compliance of the mesh contacts (see the header): one
    // solution where redundant contact points make A singular
    shift.resize(n);
    for (label a = 0; a < n; ++a)
    {
        shift(a) =
            contacts[dirs[a].first].centreBased
          ? 0
          : compliance_*A.coeff(a, a);
        A.coeffRef(a, a) += shift(a);
    }

    // A = G G^T + diag(shift), G = J W^1/2 (lcpFactors), where it has
    // fewer columns than rows: a heap of mesh pellets, whose LCP the
    // solver can then work on in body space
    factors.G.resize(0, 0);
    if (factorsPay)
    {
        bodyFactors(bodies, contacts, fixed, dirs, touched, factors);
        factors.s = shift;
    }
}


void Foam::rbd::lcpAssembly::diagonal
(
    const UList<contact>& contacts,
    const boolList& fixed,
    const std::vector<constraint>& dirs,
    Eigen::SparseMatrix<double>& A
) const
{
    // Each entry as allEntries sums it: the term of body i, then that
    // of body k (from 0: 0 + t = t exactly, so the same bits)
    const label n = dirs.size();
    A.resize(n, n);
    A.resizeNonZeros(n);
    int* outer = A.outerIndexPtr();
    int* inner = A.innerIndexPtr();
    double* value = A.valuePtr();
    for (label b = 0; b < n; ++b)
    {
        const contact& c = contacts[dirs[b].first];
        scalar v = 0;
        for (const bool kSide : {false, true})
        {
            const label body = kSide ? c.k : c.i;
            if (body < 0 || fixed[body])
            {
                continue;
            }
            const row& R = kSide ? rowsK_[b] : rowsI_[b];
            v += (R.lin & R.wLin) + (R.ang & R.wAng);
        }
        outer[b] = b;
        inner[b] = b;
        value[b] = v;
    }
    outer[n] = n;
}


void Foam::rbd::lcpAssembly::allEntries
(
    const UList<contact>& contacts,
    const boolList& fixed,
    const std::vector<constraint>& dirs,
    Eigen::SparseMatrix<double>& A
)
{
    const label n = dirs.size();

    // A column by column, into compressed storage: column b holds, for
    // each moving body of row b, the rows a on that body. An entry has
    // one term per body the two rows share, at most two, so its value does
    // not depend on the order of the terms (a + b = b + a in floating
    // point): the same A as the triplets and setFromTriplets this replaced
    // (its sort through a row-major copy was 8 % of a 500-sphere packing)
    A.resize(n, n);
    slot_.assign(n, -1);
    {
        // Entries: at most the rows on the bodies of each row
        label nnz = 0;
        for (label b = 0; b < n; ++b)
        {
            const contact& c = contacts[dirs[b].first];
            for (const label body : {c.i, c.k})
            {
                if (body >= 0 && !fixed[body])
                {
                    nnz += bodyRows_[body].size();
                }
            }
        }
        A.resizeNonZeros(nnz);
    }
    int* outer = A.outerIndexPtr();
    int* inner = A.innerIndexPtr();
    double* value = A.valuePtr();
    int e = 0;
    for (label b = 0; b < n; ++b)
    {
        outer[b] = e;
        const contact& c = contacts[dirs[b].first];
        for (const bool kSide : {false, true})
        {
            const label body = kSide ? c.k : c.i;
            if (body < 0 || fixed[body])
            {
                continue;
            }
            const row& Rb = kSide ? rowsK_[b] : rowsI_[b];
            for (const auto& ra : bodyRows_[body])
            {
                const row& Ra = ra.second ? rowsK_[ra.first] : rowsI_[ra.first];
                const scalar v = (Ra.lin & Rb.wLin) + (Ra.ang & Rb.wAng);
                const label a = ra.first;
                if (slot_[a] < 0)
                {
                    slot_[a] = e;
                    inner[e] = a;
                    value[e++] = v;
                }
                else
                {
                    value[slot_[a]] += v;
                }
            }
        }
        // Rows ascending, as Eigen keeps them; the slots free again
        sortCompressedColumn(inner, value, outer[b], e);
        for (int m = outer[b]; m < e; ++m)
        {
            slot_[inner[m]] = -1;
        }
    }
    outer[n] = e;
    A.resizeNonZeros(e);
}


void Foam::rbd::lcpAssembly::bodyFactors
(
    const UList<rigidBody>& bodies,
    const UList<contact>& contacts,
    const boolList& fixed,
    const std::vector<constraint>& dirs,
    const std::vector<label>& touched,
    lcpFactors& factors
)
{
    const label n = dirs.size();
    const label d = 6*label(touched.size());
    // Per body: its first column, and L with L L^T = I^-1 (world
    // frame; zero for a body that does not rotate)
    std::vector<Eigen::Matrix3d> sqrtInvInertia(touched.size());
    for (size_t t = 0; t < touched.size(); ++t)
    {
        const rigidBody& bd = bodies[touched[t]];
        bodyColumn_[touched[t]] = 6*label(t);
        Eigen::Matrix3d W(Eigen::Matrix3d::Zero());
        if (bd.rotates())
        {
            for (direction r = 0; r < 3; ++r)
            {
                for (direction c = 0; c < 3; ++c)
                {
                    W(r, c) = bd.invInertia()(r, c);
                }
            }
            W = W.llt().matrixL();
        }
        sqrtInvInertia[t] = W;
    }
    gTriplets_.clear();
    auto addG = [&](const label a, const label body, const row& R)
    {
        const label col = bodyColumn_[body];
        const scalar sqrtInvMass = Foam::sqrt(bodies[body].invMass());
        const Eigen::Vector3d g
        (
            sqrtInvInertia[col/6].transpose()
           *Eigen::Vector3d(R.ang.x(), R.ang.y(), R.ang.z())
        );
        for (direction k = 0; k < 3; ++k)
        {
            gTriplets_.emplace_back(a, col + k, sqrtInvMass*R.lin[k]);
            gTriplets_.emplace_back(a, col + 3 + k, g(k));
        }
    };
    for (label a = 0; a < n; ++a)
    {
        const contact& c = contacts[dirs[a].first];
        addG(a, c.i, rowsI_[a]);
        if (c.k >= 0 && !fixed[c.k])
        {
            addG(a, c.k, rowsK_[a]);
        }
    }
    factors.G.resize(n, d);
    factors.G.setFromTriplets(gTriplets_.begin(), gTriplets_.end());
    for (const label body : touched)
    {
        bodyColumn_[body] = -1;
    }
}


// ************************************************************************* //
