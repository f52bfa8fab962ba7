/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "projectedGaussSeidelLCP.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"
#include "Switch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(projectedGaussSeidelLCP, 0);
    addToRunTimeSelectionTable(lcpSolver, projectedGaussSeidelLCP, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::projectedGaussSeidelLCP::projectedGaussSeidelLCP
(
    const dictionary& coeffs
)
:
    lcpSolver(),
    tolerance_
    (
        getPositiveOrDefault(coeffs, "tolerance", 1e-6, "-", maxTolerance)
    ),
    maxIterations_(getLabelOrDefault(coeffs, "maxIterations", 1000, 1)),
    relaxation_(coeffs.getOrDefault<scalar>("relaxation", 1)),
    warmStart_(getSwitchOrDefault(coeffs, "warmStart", false))
{
    if (!(relaxation_ > 0 && relaxation_ < 2))
    {
        badEntry(coeffs, "relaxation", relaxation_, "a number in (0, 2)");
    }
    checkKnownEntries
    (
        coeffs,
        {"tolerance", "maxIterations", "relaxation", "warmStart"}
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::rbd::lcpResult Foam::rbd::projectedGaussSeidelLCP::solve
(
    const Eigen::MatrixXd& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& f
) const
{
    const label n = b.size();
    if (warmStart_ && f.size() == n && f.allFinite())
    {
        f = f.cwiseMax(0.0);
    }
    else
    {
        f = Eigen::VectorXd::Zero(n);
    }

    lcpResult result;
    if (!checkInput(A, b))
    {
        f.setZero();
        result.maxViolation = GREAT;
        return result;
    }
    if (n == 0)
    {
        result.converged = true;
        return result;
    }

    const scalar bMax = b.cwiseAbs().maxCoeff();
    const scalar aMax = A.cwiseAbs().maxCoeff();
    const scalar diagMin = 1e-14*A.diagonal().cwiseAbs().maxCoeff();

    // Inverse diagonal; 0 for contacts that act on nothing
    Eigen::VectorXd invDiag(n);
    for (label i = 0; i < n; ++i)
    {
        invDiag(i) = A(i, i) > diagMin ? 1/A(i, i) : 0;
        if (invDiag(i) == 0)
        {
            f(i) = 0;
        }
    }

    label sweep = 0;
    while (sweep < maxIterations_)
    {
        ++sweep;
        scalar residual = 0;
        for (label i = 0; i < n; ++i)
        {
            // A symmetric: column i is row i, and contiguous
            const scalar wi = A.col(i).dot(f) + b(i);
            if (invDiag(i) == 0)
            {
                // Nothing to adjust; w_i < 0 stays a violation
                residual = max(residual, -wi);
                continue;
            }
            const scalar step = -wi*invDiag(i);

            // Natural residual: the unrelaxed projected step
            residual = max(residual, mag(max(-f(i), step))*A(i, i));

            f(i) = max(scalar(0), f(i) + relaxation_*step);
        }

        const scalar wRef =
            bMax > 0 ? bMax : aMax*f.cwiseAbs().maxCoeff();
        if (residual <= tolerance_*wRef)
        {
            result.converged = true;
            break;
        }
    }

    result.iterations = sweep;
    result.maxViolation = violation(A, b, f);
    return result;
}


void Foam::rbd::projectedGaussSeidelLCP::writeCoeffs(Ostream& os) const
{
    os.writeEntry("tolerance", tolerance_);
    os.writeEntry("maxIterations", maxIterations_);
    os.writeEntry("relaxation", relaxation_);
    os.writeEntry("warmStart", Switch(warmStart_));
}


// ************************************************************************* //
