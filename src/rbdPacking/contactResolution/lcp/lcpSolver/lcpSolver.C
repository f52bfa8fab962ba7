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

Foam::scalar Foam::rbd::lcpSolver::violation
(
    const Eigen::MatrixXd& A,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& f
)
{
    const Eigen::Index n = b.size();
    if (n == 0)
    {
        return 0;
    }

    const Eigen::VectorXd w = A*f + b;
    const scalar fRef = f.cwiseAbs().maxCoeff();
    scalar wRef = b.cwiseAbs().maxCoeff();
    if (wRef == 0)
    {
        wRef = A.cwiseAbs().maxCoeff()*fRef;
    }

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
