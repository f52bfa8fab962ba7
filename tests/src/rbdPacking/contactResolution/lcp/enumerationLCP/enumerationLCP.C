/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "rbdPacking/contactResolution/lcp/enumerationLCP/enumerationLCP.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "error.H"

#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(enumerationLCP, 0);
    addToRunTimeSelectionTable(lcpSolver, enumerationLCP, dictionary);
}
}

constexpr Foam::label Foam::rbd::enumerationLCP::maxContacts;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::enumerationLCP::enumerationLCP(const dictionary& coeffs)
:
    lcpSolver(),
    tolerance_
    (
        getPositiveOrDefault(coeffs, "tolerance", 1e-9, "-", maxTolerance)
    )
{
    checkKnownEntries(coeffs, {"tolerance"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::rbd::lcpResult Foam::rbd::enumerationLCP::solve
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
    if (n > maxContacts)
    {
        FatalErrorInFunction
            << "The enumeration LCP solver tries all 2^n active sets and"
            << " is limited to n <= " << maxContacts << " contacts; got n = "
            << n << nl
            << "    Select lcpSolver baraff or projectedGaussSeidel for"
            << " larger problems." << nl
            << exit(FatalError);
    }

    Eigen::VectorXd trial(n);
    std::vector<label> S;
    S.reserve(n);

    // Sets of k members, k = 0..n, each in increasing bit-pattern order
    for (label k = 0; k <= n; ++k)
    {
        // First pattern with k bits; Gosper's hack for the next
        unsigned long set = (1ul << k) - 1;
        const unsigned long end = 1ul << n;
        while (set < end)
        {
            ++result.iterations;

            S.clear();
            for (label i = 0; i < n; ++i)
            {
                if (set & (1ul << i))
                {
                    S.push_back(i);
                }
            }

            trial.setZero();
            if (k > 0)
            {
                Eigen::MatrixXd Ass(k, k);
                Eigen::VectorXd bs(k);
                for (label r = 0; r < k; ++r)
                {
                    bs(r) = -b(S[r]);
                    for (label c = 0; c < k; ++c)
                    {
                        Ass(r, c) = A(S[r], S[c]);
                    }
                }
                const Eigen::VectorXd fs =
                    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>
                    (Ass).solve(bs);
                for (label r = 0; r < k; ++r)
                {
                    trial(S[r]) = fs(r);
                }
            }

            if (violation(A, b, trial) <= tolerance_)
            {
                f = trial.cwiseMax(0.0);
                result.maxViolation = violation(A, b, f);
                result.converged = true;
                return result;
            }

            if (k == 0)
            {
                break;
            }
            const unsigned long c = set & -set;
            const unsigned long r = set + c;
            set = (((r ^ set) >> 2)/c) | r;
        }
    }

    result.maxViolation = violation(A, b, f);
    return result;
}


void Foam::rbd::enumerationLCP::writeCoeffs(Ostream& os) const
{
    os.writeEntry("tolerance", tolerance_);
}


// ************************************************************************* //
