/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "baraffLCP.H"
#include "updatableCholesky.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "Switch.H"

#include <limits>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(baraffLCP, 0);
    addToRunTimeSelectionTable(lcpSolver, baraffLCP, dictionary);
}
}


// * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using Foam::label;
    using Foam::scalar;

    //- State of a contact in Baraff's algorithm
    enum class contactSet : char
    {
        unvisited,      // f = 0, a of any sign
        clamped,        // C:  f >= 0, a = 0
        independent,    // NC: f = 0,  a >= 0
        frozen          // d of an unbounded step: f kept, not driven
    };

    //- The clamped set C with its matrix A_CC, factorised
    class clampedSet
    {
        const Eigen::MatrixXd& A_;

        //- Contacts in C, in the order of the rows of the factor
        std::vector<label> members_;

        Foam::rbd::updatableCholesky chol_;

        //- Updated Cholesky factor in use (else dense decomposition)
        bool incremental_;

        //- Smallest accepted square of a new Cholesky pivot [1/kg]
        scalar minPivot2_;


    public:

        clampedSet
        (
            const Eigen::MatrixXd& A,
            const bool incremental,
            const scalar minPivot2
        )
        :
            A_(A),
            chol_(A.rows()),
            incremental_(incremental),
            minPivot2_(minPivot2)
        {
            members_.reserve(A.rows());
        }

        const std::vector<label>& members() const
        {
            return members_;
        }

        label size() const
        {
            return label(members_.size());
        }

        //- Rows of A for the members, column j: A_Cj
        Eigen::VectorXd column(const label j) const
        {
            Eigen::VectorXd c(members_.size());
            for (std::size_t k = 0; k < members_.size(); ++k)
            {
                c(k) = A_(members_[k], j);
            }
            return c;
        }

        void add(const label j)
        {
            if
            (
                incremental_
             && !chol_.append(column(j), A_(j, j), minPivot2_)
            )
            {
                // Numerically singular A_CC: rank-revealing from here on
                incremental_ = false;
            }
            members_.push_back(j);
        }

        void remove(const label j)
        {
            for (std::size_t k = 0; k < members_.size(); ++k)
            {
                if (members_[k] == j)
                {
                    if (incremental_)
                    {
                        chol_.remove(label(k));
                    }
                    members_.erase(members_.begin() + k);
                    return;
                }
            }
        }

        //- Overwrite x (one entry per member) by A_CC^-1 x (minimum-norm
        //  least squares in the dense fallback)
        void solveInPlace(Eigen::VectorXd& x) const
        {
            if (members_.empty())
            {
                return;
            }
            if (incremental_)
            {
                chol_.solveInPlace(x);
                return;
            }
            const label m = size();
            Eigen::MatrixXd Acc(m, m);
            for (label k = 0; k < m; ++k)
            {
                for (label l = 0; l < m; ++l)
                {
                    Acc(k, l) = A_(members_[k], members_[l]);
                }
            }
            x = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(Acc)
                .solve(x);
        }
    };
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::baraffLCP::baraffLCP(const dictionary& coeffs)
:
    lcpSolver(),
    tolerance_
    (
        getPositiveOrDefault(coeffs, "tolerance", 1e-9, "-", maxTolerance)
    ),
    pivotTolerance_
    (
        getPositiveOrDefault
        (
            coeffs, "pivotTolerance", 1e-10, "-", maxTolerance
        )
    ),
    maxPivotsPerContact_
    (
        getLabelOrDefault(coeffs, "maxPivotsPerContact", 50, 1)
    ),
    updateFactorisation_
    (
        getSwitchOrDefault(coeffs, "updateFactorisation", true)
    )
{
    checkKnownEntries
    (
        coeffs,
        {
            "tolerance", "pivotTolerance", "maxPivotsPerContact",
            "updateFactorisation"
        }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::rbd::lcpResult Foam::rbd::baraffLCP::solve
(
    const Eigen::MatrixXd& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& f
) const
{
    const label n = b.size();
    f = Eigen::VectorXd::Zero(n);

    lcpResult result;
    if (!checkInput(A, b))
    {
        result.maxViolation = GREAT;
        return result;
    }
    if (n == 0)
    {
        result.converged = true;
        return result;
    }

    const scalar aTol = tolerance_*b.cwiseAbs().maxCoeff();
    const scalar daTol = pivotTolerance_*A.diagonal().cwiseAbs().maxCoeff();
    const scalar dfTol = pivotTolerance_;
    const label maxPivots = maxPivotsPerContact_*n;
    constexpr scalar unbounded = std::numeric_limits<scalar>::infinity();

    std::vector<contactSet> set(n, contactSet::unvisited);
    clampedSet C(A, updateFactorisation_, 0.5*daTol);

    Eigen::VectorXd a(n);
    Eigen::VectorXd da(n);
    Eigen::VectorXd x;
    label pivots = 0;
    bool failed = false;        // pivot cap reached
    bool someFrozen = false;    // some contact had an unbounded step

    while (!failed)
    {
        // Fresh accelerations, against drift; f is nonzero on C and the
        // frozen contacts only, so O(n |C|)
        a = b;
        for (label i = 0; i < n; ++i)
        {
            if (f(i) != 0)
            {
                a += f(i)*A.col(i);
            }
        }

        // The contact to drive: most negative a outside C
        label d = -1;
        scalar aMin = -aTol;
        for (label i = 0; i < n; ++i)
        {
            if
            (
                set[i] != contactSet::clamped
             && set[i] != contactSet::frozen
             && a(i) < aMin
            )
            {
                d = i;
                aMin = a(i);
            }
        }
        if (d < 0)
        {
            break;
        }

        // drive_to_zero(d)
        while (true)
        {
            if (pivots >= maxPivots)
            {
                failed = true;
                break;
            }
            ++pivots;

            // fdirection: df_d = 1, A_CC df_C = -A_Cd
            const std::vector<label>& members = C.members();
            x = -C.column(d);
            C.solveInPlace(x);

            // da = A df
            da = A.col(d);
            for (std::size_t k = 0; k < members.size(); ++k)
            {
                da += x(k)*A.col(members[k]);
            }

            // maxstep
            scalar s = unbounded;
            label j = -1;
            if (da(d) > daTol)
            {
                s = max(scalar(0), -a(d)/da(d));
                j = d;
            }
            for (std::size_t k = 0; k < members.size(); ++k)
            {
                const label i = members[k];
                if (x(k) < -dfTol)
                {
                    const scalar si = max(scalar(0), -f(i)/x(k));
                    if (si < s)
                    {
                        s = si;
                        j = i;
                    }
                }
            }
            for (label i = 0; i < n; ++i)
            {
                if (set[i] == contactSet::independent && da(i) < -daTol)
                {
                    const scalar si = max(scalar(0), -a(i)/da(i));
                    if (si < s)
                    {
                        s = si;
                        j = i;
                    }
                }
            }

            if (j < 0)
            {
                // Unbounded step: no solution (y = df >= 0, A y = 0,
                // b.y = a_d < 0). Keep f_d, stop driving d.
                set[d] = contactSet::frozen;
                someFrozen = true;
                break;
            }

            // Step
            f(d) += s;
            for (std::size_t k = 0; k < members.size(); ++k)
            {
                f(members[k]) += s*x(k);
            }
            a += s*da;

            // Pivot
            if (j == d)
            {
                a(d) = 0;
                set[d] = contactSet::clamped;
                C.add(d);
                break;
            }
            else if (set[j] == contactSet::clamped)
            {
                f(j) = 0;
                set[j] = contactSet::independent;
                C.remove(j);
            }
            else
            {
                a(j) = 0;
                set[j] = contactSet::clamped;
                C.add(j);
            }
        }
    }

    // Polish f_C by one step of iterative refinement: A_CC df_C = -a_C
    if (!failed && C.size())
    {
        const std::vector<label>& members = C.members();
        Eigen::VectorXd r(members.size());
        for (std::size_t k = 0; k < members.size(); ++k)
        {
            r(k) = -(A.row(members[k]).dot(f) + b(members[k]));
        }
        C.solveInPlace(r);

        Eigen::VectorXd fNew = f;
        for (std::size_t k = 0; k < members.size(); ++k)
        {
            fNew(members[k]) += r(k);
        }
        fNew = fNew.cwiseMax(0.0);
        if (violation(A, b, fNew) < violation(A, b, f.cwiseMax(0.0)))
        {
            f = fNew;
        }
    }

    f = f.cwiseMax(0.0);

    result.iterations = pivots;
    result.maxViolation = violation(A, b, f);
    result.converged =
        !failed && !someFrozen && result.maxViolation <= tolerance_;

    return result;
}


void Foam::rbd::baraffLCP::writeCoeffs(Ostream& os) const
{
    os.writeEntry("tolerance", tolerance_);
    os.writeEntry("pivotTolerance", pivotTolerance_);
    os.writeEntry("maxPivotsPerContact", maxPivotsPerContact_);
    os.writeEntry("updateFactorisation", Switch(updateFactorisation_));
}


// ************************************************************************* //
