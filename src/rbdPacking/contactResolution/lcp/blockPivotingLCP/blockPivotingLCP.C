/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "blockPivotingLCP.H"
#include "baraffLCP.H"
#include "lcpBodySpace.H"
#include "lcpActiveSet.H"
#include "dictionaryChecks.H"
#include "addToRunTimeSelectionTable.H"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#include <Eigen/SparseCholesky>
#include <Eigen/OrderingMethods>
#include <algorithm>
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


// * * * * * * * * * * * * * * * Local Classes * * * * * * * * * * * * * * //

namespace
{
    using Foam::label;
    typedef Eigen::SparseMatrix<double> sparseMatrix;
    typedef Eigen::SimplicialLDLT
    <
        sparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>
    > sparseLDLT;
}


// * * * * * * * * * * * * * * * Private Classes * * * * * * * * * * * * * //

//- The interior point's Newton matrix A + diag(D), D > 0, factorised
//  per step: in body space where that pays, else in contact space (the
//  pattern of A, ordered and analysed once). In body space E^-1 is large
//  at loaded contacts and r - G y loses digits; the direction is not
//  refined for that: the next step's residual is taken from A itself,
//  so an inexact direction costs at most a step, and two refinement
//  steps cost 40 % of the interior point's time for answers within
//  2e-8 of each other (docs/restingSolveCost.md)
class Foam::rbd::blockPivotingLCP::newtonSystem
{
    const sparseMatrix& A_;

    //- Body space, or null
    lcpBodySpace* body_;

    //- Contact space: A with its diagonal stored, pointers to it
    sparseMatrix M_;
    std::vector<double*> diagonal_;
    Eigen::VectorXd M0_;
    sparseLDLT ldlt_;

public:

    newtonSystem(const sparseMatrix& A, lcpBodySpace* body)
    :
        A_(A),
        body_(body)
    {
        if (body_)
        {
            return;
        }
        const label n = A.rows();
        M_ = A;
        for (label i = 0; i < n; ++i)
        {
            M_.coeffRef(i, i) += 0;
        }
        M_.makeCompressed();
        diagonal_.resize(n);
        for (label j = 0; j < n; ++j)
        {
            for (sparseMatrix::InnerIterator it(M_, j); it; ++it)
            {
                if (it.row() == j)
                {
                    diagonal_[j] = &it.valueRef();
                }
            }
        }
        M0_ = M_.diagonal();
        ldlt_.analyzePattern(M_);
    }

    //- A x
    Eigen::VectorXd product(const Eigen::VectorXd& x) const
    {
        return body_ ? body_->product(x) : A_*x;
    }

    //- Factorise A + diag(D); false if that failed
    bool factorise(const Eigen::VectorXd& D)
    {
        if (body_)
        {
            return body_->factorise
            (
                (body_->compliance() + D).cwiseInverse()
            );
        }
        for (label i = 0; i < D.size(); ++i)
        {
            *diagonal_[i] = M0_(i) + D(i);
        }
        ldlt_.factorize(M_);
        return ldlt_.info() == Eigen::Success;
    }

    //- (A + diag(D))^-1 r with the last factorisation
    Eigen::VectorXd solve(const Eigen::VectorXd& r) const
    {
        if (!body_)
        {
            return ldlt_.solve(r);
        }
        return body_->apply(r);
    }
};


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::rbd::blockPivotingLCP::fallbackCoeffs()
{
    // At most four pivots per contact (baraff needs one to two on a
    // regular problem; its own default cap is 50)
    dictionary coeffs;
    coeffs.add("maxPivotsPerContact", label(4));
    return coeffs;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::blockPivotingLCP::blockPivotingLCP(const dictionary& coeffs)
:
    lcpSolver(),
    tolerance_
    (
        getPositiveOrDefault(coeffs, "tolerance", 1e-9, "-", maxTolerance)
    ),
    regularisation_
    (
        getInRangeOrDefault(coeffs, "regularisation", 1e-10, 1e-16, 1e-3, "-")
    ),
    maxIterations_(getLabelOrDefault(coeffs, "maxIterations", 200, 1)),
    interiorPointIterations_
    (
        getLabelOrDefault(coeffs, "interiorPointIterations", 50, 0)
    ),
    fallbackIterations_
    (
        getLabelOrDefault(coeffs, "fallbackIterations", 10, 1)
    ),
    fallbackSize_(getLabelOrDefault(coeffs, "fallbackSize", 400, 0)),
    fallback_(new baraffLCP(fallbackCoeffs())),
    maxUpdate_(getLabelOrDefault(coeffs, "maxUpdate", 16, 0))
{
    checkKnownEntries
    (
        coeffs,
        {
            "tolerance", "regularisation", "maxIterations",
            "interiorPointIterations", "fallbackIterations", "fallbackSize",
            "maxUpdate"
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
    return solve(A, lcpFactors(), b, guess, f);
}


Foam::rbd::lcpResult Foam::rbd::blockPivotingLCP::solve
(
    const Eigen::SparseMatrix<double>& A,
    const lcpFactors& factors,
    const Eigen::VectorXd& b,
    const std::vector<bool>& guess,
    Eigen::VectorXd& f
) const
{
    return solve(A, factors, b, guess, f, nullptr, true);
}


Foam::rbd::lcpResult Foam::rbd::blockPivotingLCP::solve
(
    const Eigen::SparseMatrix<double>& A,
    const lcpFactors& factors,
    const Eigen::VectorXd& b,
    const std::vector<bool>& guess,
    Eigen::VectorXd& f,
    activeSetFactor& kept,
    const bool exchanges
) const
{
    return solve(A, factors, b, guess, f, &kept, exchanges);
}


Foam::rbd::lcpResult Foam::rbd::blockPivotingLCP::solve
(
    const Eigen::SparseMatrix<double>& A,
    const lcpFactors& factors,
    const Eigen::VectorXd& b,
    const std::vector<bool>& guess,
    Eigen::VectorXd& f,
    activeSetFactor* kept,
    const bool exchangesAsked
) const
{
    // The exchanges are the solver where the interior point is off
    const bool exchanges = exchangesAsked || interiorPointIterations_ <= 0;

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
    // factorised without ordering again. An island keeps its contacts for
    // many steps: the ordering of a pattern seen before is reused.
    //
    // Body space, where A's factors make it the smaller system: the
    // candidate (A_FF + eps I) f_F = -b_F by the Woodbury identity, E^-1 =
    // 1/(s + eps) on F and 0 elsewhere, refined in the same way
    autoPtr<lcpBodySpace> body;
    orderingCache::permutation natural;
    if (lcpBodySpace::pays(A, factors))
    {
        body.reset(new lcpBodySpace(factors));
        natural.setIdentity(n);
    }
    const orderingCache::permutation& order =
        body.valid() ? natural : orderings_.order(A);
    const Eigen::VectorXd minusB(-b);

    // The factors go to the caller's kept factor where given (contact
    // space), else to this solver's work space
    if (body.valid())
    {
        kept = nullptr;
    }
    std::vector<label> pos(n), members, infeasible;
    if (!kept)
    {
        own_.invalidate();
    }
    activeSetFactor& fac = kept ? *kept : own_;
    Eigen::VectorXd z(Eigen::VectorXd::Zero(n)), w(n);

    // Judice-Pires: block exchanges while the number of infeasible
    // contacts falls (or within three chances); once they cycle, the
    // interior-point method takes over
    blockExchangeProgress progress(n);

    const label iterations =
        n <= fallbackSize_
      ? min(maxIterations_, fallbackIterations_)
      : maxIterations_;

    for (label iter = 0; exchanges && iter < iterations; ++iter)
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

        // The candidate: from the factor of the last factorised set
        // where this set differs from it in at most maxUpdate contacts
        // (activeSetUpdate: the first candidate of a kept factor's set
        // costs two triangular solves), else one factorisation, which
        // becomes that set. On failure, not expected as A_FF + eps I is
        // positive definite, the interior point and the fallback take
        // over
        const bool contactSpace = !body.valid();
        const bool factorised = contactSpace && fac.holds(members, eps);
        const bool updated =
            contactSpace && !factorised && fac.updates && fac.valid
         && fac.eps == eps
         && fac.update.solve
            (
                A, fac.members, fac.ldlt, pos, eps, maxUpdate_, minusB, z
            );
        if (!updated)
        {
            if (contactSpace && !factorised)
            {
                fac.invalidate();
            }
            if
            (
                !solveActiveSet
                (
                    A, body.get(), members, pos, eps, minusB, fac.ldlt,
                    fac.system, z, factorised
                )
            )
            {
                break;
            }
            if (contactSpace && !factorised)
            {
                fac.set(members, eps);
            }
        }
        w = (body.valid() ? body->product(z) : Eigen::VectorXd(A*z)) + b;
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

        const label nInfeasible = infeasible.size();
        if (!progress.proceed(nInfeasible))
        {
            // The block exchanges cycle
            break;
        }
        for (const label i : infeasible)
        {
            inF[i] = !inF[i];
        }
    }

    // Without exchanges no candidate (f = 0 would beat any answer of the
    // interior point: violation() is relative to max |f|)
    f = z.cwiseMax(0.0);
    scalar v = exchanges ? violation(A, b, f) : GREAT;

    // Block exchanges cycled, ran out or were not asked for: the interior
    // point
    if (!result.converged && interiorPointIterations_ > 0)
    {
        Eigen::VectorXd fi;
        result.newtonSteps = interiorPoint(A, body.get(), b, diag, fi);
        result.iterations += result.newtonSteps;
        const scalar vi = violation(A, b, fi);
        if (vi <= tolerance_ || vi < v)
        {
            f = fi;
            v = vi;
            result.converged = vi <= tolerance_;
        }
    }

    // Asked for the interior point alone, which did not solve it: the
    // block exchanges after all, from the guess (and the fallback), as
    // without the request
    if (!exchanges && !result.converged)
    {
        const lcpResult first = result;
        result = solve(A, factors, b, guess, f, kept, true);
        result.iterations += first.iterations;
        result.newtonSteps += first.newtonSteps;
        return result;
    }

    // A small problem that is still not solved, and not even within
    // usableViolation: baraff (dense, rank-aware), with a pivot cap. Not
    // for the interior point's stalls a little above the tolerance:
    // there baraff's rank-revealing pivots, O(n^3) each once A_CC is
    // nearly singular, took up to 44 s (13 700 pivots; 3.4 s with the cap)
    // on a 273-contact island of the spheres tutorial. Its f is taken when
    // it meets the tolerance, whatever baraff says of frozen contacts.
    if (!result.converged && v > usableViolation && n <= fallbackSize_)
    {
        Eigen::VectorXd fb;
        const lcpResult rb = fallback_->solve(Eigen::MatrixXd(A), b, fb);
        result.iterations += rb.iterations;
        const scalar vb = violation(A, b, fb);
        if (vb <= tolerance_ || vb < v)
        {
            f = fb;
            v = vb;
            result.converged = vb <= tolerance_;
        }
    }

    result.maxViolation = v;
    if (!result.converged && debug)
    {
        writeProblem(A, b, guess, eps);
    }
    return result;
}


Foam::label Foam::rbd::blockPivotingLCP::interiorPoint
(
    const Eigen::SparseMatrix<double>& A,
    lcpBodySpace* body,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& diag,
    Eigen::VectorXd& f
) const
{
    const label n = b.size();
    const scalar bRef = b.cwiseAbs().maxCoeff();

    // Strictly positive start on the problem's scales: d, the largest
    // acceleration the forces must cancel (max -b_i; max |b| if none is
    // negative), not max |b|, which contacts within the band but apart
    // set (b = 2 (gap + h v_n)/h^2 + ..., up to 2e6 m/s^2 in a heap at
    // h = 2.4e-5 s: 21.8 Newton steps a solve from that scale, 7.5 from
    // this one with the same stopping rule; docs/restingSolveCost.md,
    // "Twenty-sixth session").
    // w: the start's A f + b where positive, plus d; then f_i = d^2/(w_i
    // max A_ii), so that every product f_i w_i is the same
    const scalar bNeg = -b.minCoeff();
    const scalar d = bNeg > 0 ? bNeg : max(bRef, VSMALL);
    const scalar fScale = d/diag.maxCoeff();
    f = Eigen::VectorXd::Constant(n, fScale);
    Eigen::VectorXd w
    (
        (A*f + b).cwiseMax(0.0) + Eigen::VectorXd::Constant(n, d)
    );
    f = (fScale*d)*w.cwiseInverse();

    // Done when f meets the tolerance on the load's scale d (not on max
    // |b|, which the contacts apart set: at 2e6 m/s^2 it held the touching
    // contacts' accelerations only to 2e-3 m/s^2, and from this start the
    // interior point stopped there: the STL pellets of the test suite
    // then reached 1.8 % dp); at least loadScaleFloor max |b|
    const scalar wScale = stoppingScale(d, bRef);

    newtonSystem newton(A, body);

    // The largest step in (0, 1] along (df, dw) that keeps f, w > 0
    auto maxStep = [&](const Eigen::VectorXd& df, const Eigen::VectorXd& dw)
    {
        scalar alpha = 1;
        for (label i = 0; i < n; ++i)
        {
            if (df(i) < 0)
            {
                alpha = min(alpha, -f(i)/df(i));
            }
            if (dw(i) < 0)
            {
                alpha = min(alpha, -w(i)/dw(i));
            }
        }
        return alpha;
    };

    // Stalled: no halving of the violation in this many steps (an
    // infeasible problem; on the way to a solution the violation can stay
    // put for five steps, as on a 262-contact island of the tutorial)
    const label stallSteps = 10;
    scalar best = GREAT;
    label bestStep = 0;

    // max |A_ij|, the scale violation() needs, once for the solve
    scalar aMax = 0;
    for (Eigen::Index k = 0; k < A.nonZeros(); ++k)
    {
        aMax = max(aMax, mag(A.valuePtr()[k]));
    }

    label step = 0;
    for (; step < interiorPointIterations_; ++step)
    {
        // Residual of w = A f + b; done when f itself solves the LCP
        const Eigen::VectorXd wf(newton.product(f) + b);
        const Eigen::VectorXd r(wf - w);
        const scalar v =
            bRef > 0
          ? violationOnScale(wf, f, wScale)
          : violation(wf, b, f, aMax);
        if (v <= tolerance_)
        {
            break;
        }
        if (v < 0.5*best)
        {
            best = v;
            bestStep = step;
        }
        else if
        (
            step - bestStep >= stallSteps
         || (
                step - bestStep >= loadScaleStallSteps
             && violation(wf, b, f, aMax) <= tolerance_
            )
        )
        {
            // Stalled; or stalled on the load's scale with the tolerance
            // met on max |b| (round-off keeps the stricter one out of
            // reach: an island whose load is small against its apart
            // contacts' b)
            break;
        }
        const scalar mu = f.dot(w)/n;

        if (!newton.factorise(w.cwiseQuotient(f)))
        {
            break;
        }

        // Predictor (affine-scaling) direction: the Newton step for
        // A df - dw = -r, W df + F dw = -F W e
        const Eigen::VectorXd dfAff(newton.solve(-(w + r)));
        const Eigen::VectorXd dwAff(newton.product(dfAff) + r);
        const scalar alphaAff = maxStep(dfAff, dwAff);
        const scalar muAff =
            (f + alphaAff*dfAff).dot(w + alphaAff*dwAff)/n;
        const scalar sigma = pow3(muAff/mu);

        // Corrector: centring sigma mu and the second-order term
        const Eigen::VectorXd df
        (
            newton.solve
            (
                -r - w
              + (
                    Eigen::VectorXd::Constant(n, sigma*mu)
                  - dfAff.cwiseProduct(dwAff)
                ).cwiseQuotient(f)
            )
        );
        const Eigen::VectorXd dw(newton.product(df) + r);
        if (!df.allFinite() || !dw.allFinite())
        {
            break;
        }
        const scalar alpha = min(scalar(1), 0.99*maxStep(df, dw));
        f += alpha*df;
        w += alpha*dw;
    }

    // The iterate is strictly positive: forces below the tolerance at
    // contacts whose gap dominates are set to zero (if the whole still
    // meets the tolerance), so the active set passed on to the next step
    // is the contacts that carry the load
    const Eigen::VectorXd wf(A*f + b);
    const scalar fRef = f.cwiseAbs().maxCoeff();
    Eigen::VectorXd pure(f);
    for (label i = 0; i < n; ++i)
    {
        if (f(i) <= tolerance_*fRef && f(i)*bRef <= wf(i)*fRef)
        {
            pure(i) = 0;
        }
    }
    if
    (
        violation(Eigen::VectorXd(A*pure + b), b, pure, aMax)
     <= max(tolerance_, violation(wf, b, f, aMax))
    )
    {
        f = pure;
    }
    return step;
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
    os.writeEntry("interiorPointIterations", interiorPointIterations_);
    os.writeEntry("fallbackIterations", fallbackIterations_);
    os.writeEntry("fallbackSize", fallbackSize_);
    os.writeEntry("maxUpdate", maxUpdate_);
}


// ************************************************************************* //
