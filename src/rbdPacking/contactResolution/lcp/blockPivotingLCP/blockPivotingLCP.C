/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "blockPivotingLCP.H"
#include "baraffLCP.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#include <Eigen/SparseCholesky>
#include <Eigen/OrderingMethods>
#include <fstream>
#pragma GCC diagnostic pop

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(blockPivotingLCP, 0);
    addToRunTimeSelectionTable(lcpSolver, blockPivotingLCP, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::blockPivotingLCP::blockPivotingLCP(const dictionary& coeffs)
:
    lcpSolver(),
    tolerance_(getPositiveOrDefault(coeffs, "tolerance", 1e-9, "-")),
    regularisation_
    (
        getInRangeOrDefault(coeffs, "regularisation", 1e-10, 1e-16, 1e-3, "-")
    ),
    maxIterations_(getLabelOrDefault(coeffs, "maxIterations", 200, 1)),
    fallbackIterations_
    (
        getLabelOrDefault(coeffs, "fallbackIterations", 10, 1)
    ),
    fallbackSize_(getLabelOrDefault(coeffs, "fallbackSize", 400, 0)),
    smoothingSweeps_(getLabelOrDefault(coeffs, "smoothingSweeps", 10, 1)),
    fallback_(new baraffLCP(dictionary()))
{
    checkKnownEntries
    (
        coeffs,
        {
            "tolerance", "regularisation", "maxIterations",
            "fallbackIterations", "fallbackSize", "smoothingSweeps"
        }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::rbd::lcpResult Foam::rbd::blockPivotingLCP::solve
(
    const Eigen::MatrixXd& A,
    const Eigen::VectorXd& b,
    Eigen::VectorXd& f
) const
{
    if (!checkInput(A, b))
    {
        f = Eigen::VectorXd::Zero(b.size());
        lcpResult result;
        result.maxViolation = GREAT;
        return result;
    }
    const Eigen::SparseMatrix<double> As(A.sparseView());
    return solve(As, b, std::vector<bool>(), f);
}


Foam::rbd::lcpResult Foam::rbd::blockPivotingLCP::solve
(
    const Eigen::SparseMatrix<double>& A,
    const Eigen::VectorXd& b,
    const std::vector<bool>& guess,
    Eigen::VectorXd& f
) const
{
    typedef Eigen::SparseMatrix<double> sparseMatrix;

    const label n = b.size();
    lcpResult result;
    f = Eigen::VectorXd::Zero(n);

    if (A.rows() != A.cols() || A.rows() != n)
    {
        FatalErrorInFunction
            << "LCP of inconsistent size: A is " << label(A.rows()) << " x "
            << label(A.cols()) << ", b has " << n << " entries" << nl
            << exit(FatalError);
    }
    bool finite = b.allFinite();
    scalar diagMax = 0;
    Eigen::VectorXd diag(Eigen::VectorXd::Zero(n));
    for (label j = 0; j < n && finite; ++j)
    {
        for (sparseMatrix::InnerIterator it(A, j); it; ++it)
        {
            finite = finite && std::isfinite(it.value());
            if (it.row() == j)
            {
                diag(j) = it.value();
                diagMax = max(diagMax, it.value());
            }
        }
    }
    if (!finite)
    {
        result.maxViolation = GREAT;
        return result;
    }

    const scalar bRef = n ? b.cwiseAbs().maxCoeff() : 0;
    if (n == 0 || bRef == 0 || diagMax <= 0)
    {
        // f = 0 is the solution, unless a contact that acts on nothing is
        // pushed into interpenetration (then no f helps)
        result.converged = (n == 0) || b.minCoeff() >= 0;
        result.maxViolation = violation(A, b, f);
        return result;
    }
    const scalar eps = regularisation_*diagMax;

    // The active set F: the guess, else the contacts pushed together
    std::vector<bool> inF(n);
    for (label i = 0; i < n; ++i)
    {
        inF[i] = label(guess.size()) == n ? guess[i] : b(i) < 0;
    }

    // One fill-reducing (AMD) ordering of A for the whole solve: every
    // A_FF is assembled in the order it induces on F (a principal
    // submatrix keeps the elimination order's sparsity benefits), and
    // factorised without ordering again
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
    Eigen::AMDOrdering<int>()(A, order);

    std::vector<label> pos(n), members, infeasible;
    std::vector<Eigen::Triplet<double>> triplets;
    Eigen::SimplicialLDLT
    <
        sparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>
    > ldlt;
    Eigen::VectorXd z(n), w(n);

    // Judice-Pires: block exchanges while the number of infeasible
    // contacts falls (or within three chances), else Gauss-Seidel
    // smoothing picks the next active set
    label fewest = n + 1;
    label chances = 3;

    // Gauss-Seidel smoothing, once block exchanges cycle; its candidates
    // are accepted within ten times the tolerance: the block candidates of
    // a degenerate island cycle at round-off just above it (see the
    // header)
    bool smoothing = false;
    const scalar cyclingTolerance = 10*tolerance_;
    Eigen::VectorXd fs;
    auto objective = [&](const Eigen::VectorXd& x)
    {
        return 0.5*x.dot(A*x) + 0.5*eps*x.squaredNorm() + b.dot(x);
    };

    const label iterations =
        n <= fallbackSize_
      ? min(maxIterations_, fallbackIterations_)
      : maxIterations_;

    for (label iter = 0; iter < iterations; ++iter)
    {
        members.clear();
        for (label k = 0; k < n; ++k)
        {
            const label i = order.indices()(k);
            pos[i] = inF[i] ? label(members.size()) : -1;
            if (inF[i])
            {
                members.push_back(i);
            }
        }

        z.setZero();
        const label m = members.size();
        if (m)
        {
            triplets.clear();
            for (label k = 0; k < m; ++k)
            {
                const label j = members[k];
                for (sparseMatrix::InnerIterator it(A, j); it; ++it)
                {
                    const label r = pos[it.row()];
                    if (r >= 0)
                    {
                        triplets.emplace_back(r, k, it.value());
                    }
                }
                triplets.emplace_back(k, k, eps);
            }
            sparseMatrix AFF(m, m);
            AFF.setFromTriplets(triplets.begin(), triplets.end());
            ldlt.compute(AFF);
            if (ldlt.info() != Eigen::Success)
            {
                // Not expected (A_FF + eps I is positive definite): leave
                // it to the fallback, or to f = 0
                break;
            }
            Eigen::VectorXd rhs(m);
            for (label k = 0; k < m; ++k)
            {
                rhs(k) = -b(members[k]);
            }
            // Iterative refinement with the same factor: the solution of
            // A_FF f = -b_F itself where that system is consistent (the
            // compliance eps f would otherwise let a loaded stack sink)
            Eigen::VectorXd zF(ldlt.solve(rhs));
            for (label refine = 0; refine < 2; ++refine)
            {
                const Eigen::VectorXd r(rhs - (AFF*zF - eps*zF));
                zF += ldlt.solve(r);
            }
            for (label k = 0; k < m; ++k)
            {
                z(members[k]) = zF(k);
            }
        }
        w = A*z + b;
        result.iterations = iter + 1;

        const scalar fRef = z.cwiseAbs().maxCoeff();
        infeasible.clear();
        for (label i = 0; i < n; ++i)
        {
            if
            (
                inF[i] ? z(i) < -tolerance_*fRef : w(i) < -tolerance_*bRef
            )
            {
                infeasible.push_back(i);
            }
        }

        if (infeasible.empty())
        {
            // w_F = 0 up to round-off, unless A_FF f = -b_F has no
            // solution: no finite f solves the LCP (bodies driven into
            // each other), and f runs away like 1/eps
            scalar wF = 0;
            for (const label i : members)
            {
                wF = max(wF, mag(w(i)));
            }
            result.converged = wF <= std::sqrt(tolerance_)*bRef;
            break;
        }

        if (!smoothing)
        {
            const label nInfeasible = infeasible.size();
            if (nInfeasible < fewest)
            {
                fewest = nInfeasible;
                chances = 3;
            }
            else if (chances > 0)
            {
                --chances;
            }
            else
            {
                smoothing = true;
                fs = z.cwiseMax(0.0);
            }
            if (!smoothing)
            {
                for (const label i : infeasible)
                {
                    inF[i] = !inF[i];
                }
                continue;
            }
        }

        // Block exchanges cycle: from here on, projected Gauss-Seidel
        // sweeps on the regularised problem pick the active set of the
        // next subspace solve, started from the better of the last
        // sweep's iterate and the projected subspace solution; both steps
        // lower the convex objective 1/2 f.(A + eps I) f + b.f, so this
        // converges (Silcowitz, Niebe and Erleben's PGS subspace
        // minimisation)
        {
            const Eigen::VectorXd zp(z.cwiseMax(0.0));
            if (violation(A, b, zp) <= cyclingTolerance)
            {
                // The projected subspace solution solves it
                z = zp;
                result.converged = true;
                break;
            }
            if (objective(zp) < objective(fs))
            {
                fs = zp;
            }
        }
        Eigen::VectorXd ws(A*fs + b + eps*fs);
        for (label sweep = 0; sweep < smoothingSweeps_; ++sweep)
        {
            for (label j = 0; j < n; ++j)
            {
                const scalar fj = max(fs(j) - ws(j)/(diag(j) + eps), 0.0);
                const scalar df = fj - fs(j);
                if (df != 0)
                {
                    fs(j) = fj;
                    for (sparseMatrix::InnerIterator it(A, j); it; ++it)
                    {
                        ws(it.row()) += it.value()*df;
                    }
                    ws(j) += eps*df;
                }
            }
        }
        // The smoothed iterate may itself solve the problem (the block
        // exchanges of a degenerate problem, singular A with forces and
        // gaps both zero at some contacts, can cycle between candidates
        // that miss the tolerance by round-off while the iterate meets it)
        if (violation(A, b, fs) <= cyclingTolerance)
        {
            z = fs;
            result.converged = true;
            result.iterations = iter + 1;
            break;
        }
        for (label i = 0; i < n; ++i)
        {
            inF[i] = fs(i) > 0;
        }
    }

    if (!result.converged && n <= fallbackSize_)
    {
        const label pivoted = result.iterations;
        result = fallback_->solve(Eigen::MatrixXd(A), b, f);
        result.iterations += pivoted;
        if (!result.converged && debug)
        {
            writeProblem(A, b, guess, eps);
        }
        return result;
    }

    f = z.cwiseMax(0.0);
    if (!result.converged && smoothing && objective(fs) < objective(f))
    {
        f = fs;
    }
    result.maxViolation = violation(A, b, f);
    if (!result.converged && debug)
    {
        writeProblem(A, b, guess, eps);
    }
    return result;
}


void Foam::rbd::blockPivotingLCP::writeProblem
(
    const Eigen::SparseMatrix<double>& A,
    const Eigen::VectorXd& b,
    const std::vector<bool>& guess,
    const scalar eps
)
{
    // The first maxWritten problems of the run: a bed that fails one
    // usually fails many alike
    const label maxWritten = 10;
    static label written = 0;
    if (written >= maxWritten)
    {
        return;
    }
    const label n = b.size();
    const fileName name("blockPivotingLCP" + Foam::name(written++) + ".lcp");
    std::ofstream os(name);
    os.precision(17);
    os  << n << ' ' << A.nonZeros() << ' ' << eps << '\n';
    for (label j = 0; j < n; ++j)
    {
        for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
        {
            os  << it.row() << ' ' << j << ' ' << it.value() << '\n';
        }
    }
    for (label j = 0; j < n; ++j)
    {
        os  << b(j) << ' '
            << (label(guess.size()) == n ? label(guess[j]) : -1) << '\n';
    }
    Info<< "blockPivotingLCP: unsolved problem of " << n
        << " contacts written to " << name << endl;
}


void Foam::rbd::blockPivotingLCP::writeCoeffs(Ostream& os) const
{
    os.writeEntry("tolerance", tolerance_);
    os.writeEntry("regularisation", regularisation_);
    os.writeEntry("maxIterations", maxIterations_);
    os.writeEntry("fallbackIterations", fallbackIterations_);
    os.writeEntry("fallbackSize", fallbackSize_);
    os.writeEntry("smoothingSweeps", smoothingSweeps_);
}


// ************************************************************************* //
