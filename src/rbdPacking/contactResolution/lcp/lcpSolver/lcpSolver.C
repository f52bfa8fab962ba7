/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "lcpSolver.H"
#include "error.H"
#include "Switch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(lcpSolver, 0);
    defineRunTimeSelectionTable(lcpSolver, dictionary);
}
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::lcpSolver::write(Ostream& os) const
{
    os.writeEntry("lcpSolver", type());
    os.beginBlock(word(type() + "Coeffs"));
    writeCoeffs(os);
    os.endBlock();
}


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::rbd::lcpResult Foam::rbd::lcpSolver::solve
(
    const Eigen::SparseMatrix<double>& A,
    const Eigen::VectorXd& b,
    const std::vector<bool>& guess,
    Eigen::VectorXd& f
) const
{
    return solve(Eigen::MatrixXd(A), b, f);
}


Foam::rbd::lcpResult Foam::rbd::lcpSolver::solve
(
    const Eigen::SparseMatrix<double>& A,
    const lcpFactors&,
    const Eigen::VectorXd& b,
    const std::vector<bool>& guess,
    Eigen::VectorXd& f
) const
{
    return solve(A, b, guess, f);
}


Foam::rbd::lcpResult Foam::rbd::lcpSolver::solve
(
    const Eigen::SparseMatrix<double>& A,
    const lcpFactors& factors,
    const Eigen::VectorXd& b,
    const std::vector<bool>& guess,
    Eigen::VectorXd& f,
    activeSetFactor&,
    const bool
) const
{
    return solve(A, factors, b, guess, f);
}


Foam::scalar Foam::rbd::lcpSolver::violation
(
    const Eigen::MatrixXd& A,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& f
)
{
    if (b.size() == 0)
    {
        return 0;
    }
    return violation(A*f + b, b, f, A.cwiseAbs().maxCoeff());
}


Foam::scalar Foam::rbd::lcpSolver::violation
(
    const Eigen::SparseMatrix<double>& A,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& f
)
{
    if (b.size() == 0)
    {
        return 0;
    }
    scalar aMax = 0;
    for (Eigen::Index k = 0; k < A.nonZeros(); ++k)
    {
        aMax = max(aMax, mag(A.valuePtr()[k]));
    }
    return violation(Eigen::VectorXd(A*f + b), b, f, aMax);
}


Foam::scalar Foam::rbd::lcpSolver::violation
(
    const Eigen::VectorXd& w,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& f,
    const scalar aMax
)
{
    if (b.size() == 0)
    {
        return 0;
    }

    scalar wRef = b.cwiseAbs().maxCoeff();
    if (wRef == 0)
    {
        wRef = aMax*f.cwiseAbs().maxCoeff();
    }
    return violationOnScale(w, f, wRef);
}


Foam::scalar Foam::rbd::lcpSolver::violationOnScale
(
    const Eigen::VectorXd& w,
    const Eigen::VectorXd& f,
    const scalar wRef
)
{
    if (w.size() == 0)
    {
        return 0;
    }

    const scalar fRef = f.cwiseAbs().maxCoeff();
    if (!std::isfinite(fRef) || !std::isfinite(wRef) || !w.allFinite())
    {
        return GREAT;
    }

    scalar v = 0;
    if (fRef > 0)
    {
        v = max(v, -f.minCoeff()/fRef);
    }
    if (wRef > 0)
    {
        v = max(v, -w.minCoeff()/wRef);
    }
    if (fRef > 0 && wRef > 0)
    {
        v = max(v, f.cwiseProduct(w).cwiseAbs().maxCoeff()/(fRef*wRef));
    }
    return v;
}


bool Foam::rbd::lcpSolver::checkInput
(
    const Eigen::MatrixXd& A,
    const Eigen::VectorXd& b
)
{
    if (A.rows() != A.cols() || A.rows() != b.size())
    {
        FatalErrorInFunction
            << "LCP of inconsistent size: A is " << label(A.rows()) << " x "
            << label(A.cols()) << ", b has " << label(b.size())
            << " entries" << nl
            << exit(FatalError);
    }
    return A.allFinite() && b.allFinite();
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::rbd::operator<<(Ostream& os, const lcpResult& r)
{
    os  << "converged " << Switch(r.converged).c_str()
        << ", iterations " << r.iterations
        << ", maxViolation " << r.maxViolation;
    return os;
}


Foam::Ostream& Foam::rbd::operator<<(Ostream& os, const lcpSolver& solver)
{
    solver.write(os);
    return os;
}


// ************************************************************************* //
