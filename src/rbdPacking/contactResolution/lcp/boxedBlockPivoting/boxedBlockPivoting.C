/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "boxedBlockPivoting.H"
#include "lcpActiveSet.H"
#include "autoPtr.H"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#include <Eigen/SparseCholesky>
#include <Eigen/OrderingMethods>
#pragma GCC diagnostic pop

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::boxedBlockPivoting::boxedBlockPivoting
(
    const scalar tolerance,
    const scalar regularisation,
    const label maxIterations,
    const label interiorPointIterations
)
:
    tolerance_(tolerance),
    regularisation_(regularisation),
    maxIterations_(maxIterations),
    interiorPointIterations_(interiorPointIterations)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::boxedBlockPivoting::violation
(
    const Eigen::VectorXd& w,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& lo,
    const Eigen::VectorXd& hi,
    const Eigen::VectorXd& x
)
{
    if (b.size() == 0)
    {
        return 0;
    }
    return violationOnScale(w, lo, hi, x, b.cwiseAbs().maxCoeff());
}


Foam::scalar Foam::rbd::boxedBlockPivoting::violationOnScale
(
    const Eigen::VectorXd& w,
    const Eigen::VectorXd& lo,
    const Eigen::VectorXd& hi,
    const Eigen::VectorXd& x,
    const scalar wRef
)
{
    const label n = w.size();
    if (n == 0)
    {
        return 0;
    }
    const scalar xRef = x.cwiseAbs().maxCoeff();
    if (!std::isfinite(xRef) || !w.allFinite())
    {
        return GREAT;
    }

    scalar v = 0;
    for (label i = 0; i < n; ++i)
    {
        if (xRef > 0)
        {
            v = max(v, (lo(i) - x(i))/xRef);
            v = max(v, (x(i) - hi(i))/xRef);
        }
        if (wRef > 0 && w(i) < 0)
        {
            v = max
            (
                v,
                std::isfinite(hi(i))
              ? (xRef > 0 ? (hi(i) - x(i))*(-w(i))/(xRef*wRef) : 0)
              : -w(i)/wRef
            );
        }
        else if (wRef > 0 && w(i) > 0 && xRef > 0)
        {
            v = max(v, (x(i) - lo(i))*w(i)/(xRef*wRef));
        }
    }
    return v;
}



Foam::scalar Foam::rbd::boxedBlockPivoting::startScale
(
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& lo,
    const Eigen::VectorXd& hi
)
{
    scalar demand = 0;
    for (Eigen::Index i = 0; i < b.size(); ++i)
    {
        if (lo(i) < hi(i))
        {
            demand = max(demand, std::isfinite(hi(i)) ? mag(b(i)) : -b(i));
        }
    }
    return demand > 0 ? demand : max(b.cwiseAbs().maxCoeff(), VSMALL);
}


Foam::label Foam::rbd::boxedBlockPivoting::interiorPoint
(
    const Eigen::SparseMatrix<double>& A,
    lcpBodySpace* body,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& lo,
    const Eigen::VectorXd& hi,
    const scalar diagMax,
    Eigen::VectorXd& x
) const
{
    typedef Eigen::SparseMatrix<double> sparseMatrix;

    const label n = b.size();

    // The variables that move (lo < hi), and which have an upper bound
    std::vector<bool> moves(n), upper(n);
    label nMoving = 0;
    for (label i = 0; i < n; ++i)
    {
        moves[i] = lo(i) < hi(i);
        upper[i] = moves[i] && std::isfinite(hi(i));
        nMoving += moves[i];
    }
    x = lo;
    if (nMoving == 0)
    {
        return 0;
    }

    auto product = [&](const Eigen::VectorXd& y)
    {
        return body ? body->product(y) : Eigen::VectorXd(A*y);
    };

    // The start's scales: the largest acceleration the forces must cancel
    // (startScale), not max |b|: a contact within the band but apart has
    // b = 2 (gap + h v_n)/h^2 + ..., up to 2e6 m/s^2 at h = 2.4e-5 s in
    // a heap, it carries nothing, and a start on its scale left the Newton
    // steps 13 orders of s z to reduce (20.5 steps a solve on the heap of
    // docs/restingSolveCost.md, "Twenty-sixth session"; 14 from this one
    // with the same stopping rule)
    const scalar demand = startScale(b, lo, hi);
    const scalar xScale = demand/diagMax;

    // Done when x meets the tolerance on the demand's scale (not on max
    // |b|, which the contacts apart set: at 2e6 m/s^2 it held the
    // touching contacts' accelerations only to 2e-3 m/s^2, and from this
    // start the interior point stopped there), at least loadScaleFloor
    // max |b|; b = 0: as violation(), no w terms
    const scalar bMax = b.cwiseAbs().maxCoeff();
    const scalar wScale = lcpSolver::stoppingScale(demand, bMax);

    // Strictly interior start: the middle of a finite box, xScale above an
    // open bound; multipliers of the start's w (z1 - z2 = w where they
    // can) plus the demand, and an open bound's gap s1 then shrunk to
    // xScale demand/z1 so that s1 z1 is the same for all such rows
    Eigen::VectorXd s1(Eigen::VectorXd::Ones(n)), s2(s1), z1(s1), z2(s1);
    for (label i = 0; i < n; ++i)
    {
        if (moves[i])
        {
            s1(i) = upper[i] ? 0.5*(hi(i) - lo(i)) : xScale;
            x(i) = lo(i) + s1(i);
            s2(i) = s1(i);
        }
    }
    const Eigen::VectorXd w0(product(x) + b);
    for (label i = 0; i < n; ++i)
    {
        if (!moves[i])
        {
            continue;
        }
        z1(i) = max(w0(i), scalar(0)) + demand;
        if (upper[i])
        {
            z2(i) = max(-w0(i), scalar(0)) + demand;
        }
        else
        {
            s1(i) = xScale*demand/z1(i);
            x(i) = lo(i) + s1(i);
        }
    }

    // The Newton matrix A + D on the moving variables: in body space, or
    // a sparse LDL^T of its pattern (analysed once)
    sparseMatrix M;
    std::vector<label> pos(n, -1), members;
    Eigen::SimplicialLDLT
    <
        sparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>
    > ldlt;
    std::vector<double*> diagonal;
    Eigen::VectorXd M0;
    if (!body)
    {
        for (label i = 0; i < n; ++i)
        {
            if (moves[i])
            {
                pos[i] = members.size();
                members.push_back(i);
            }
        }
        const label m = members.size();
        std::vector<Eigen::Triplet<double>> triplets;
        for (label k = 0; k < m; ++k)
        {
            for (sparseMatrix::InnerIterator it(A, members[k]); it; ++it)
            {
                if (pos[it.row()] >= 0)
                {
                    triplets.emplace_back(pos[it.row()], k, it.value());
                }
            }
            triplets.emplace_back(k, k, 0.0);
        }
        M.resize(m, m);
        M.setFromTriplets(triplets.begin(), triplets.end());
        M.makeCompressed();
        diagonal.resize(m);
        for (label k = 0; k < m; ++k)
        {
            for (sparseMatrix::InnerIterator it(M, k); it; ++it)
            {
                if (it.row() == k)
                {
                    diagonal[k] = &it.valueRef();
                }
            }
        }
        M0 = M.diagonal();
        ldlt.analyzePattern(M);
    }
    Eigen::VectorXd D(Eigen::VectorXd::Zero(n));

    auto factorise = [&]()
    {
        if (body)
        {
            Eigen::VectorXd Einv(Eigen::VectorXd::Zero(n));
            for (label i = 0; i < n; ++i)
            {
                if (moves[i])
                {
                    Einv(i) = 1/(body->compliance()(i) + D(i));
                }
            }
            return body->factorise(Einv);
        }
        for (size_t k = 0; k < members.size(); ++k)
        {
            *diagonal[k] = M0(k) + D(members[k]);
        }
        ldlt.factorize(M);
        return ldlt.info() == Eigen::Success;
    };

    // (A + D)^-1 r on the moving variables (0 on the others). In body
    // space not refined: each step's residual comes from A itself, so an
    // inexact direction costs at most a step, and two refinement steps
    // took 30 % of the coupled solve's time for answers within 2e-4 of
    // each other, never a worse one (docs/restingSolveCost.md)
    auto solveNewton = [&](const Eigen::VectorXd& r)
    {
        if (body)
        {
            return Eigen::VectorXd(body->apply(r));
        }
        Eigen::VectorXd y(Eigen::VectorXd::Zero(n));
        Eigen::VectorXd rm(members.size());
        for (size_t k = 0; k < members.size(); ++k)
        {
            rm(k) = r(members[k]);
        }
        const Eigen::VectorXd ym(ldlt.solve(rm));
        for (size_t k = 0; k < members.size(); ++k)
        {
            y(members[k]) = ym(k);
        }
        return y;
    };

    // Complementarity products and their mean
    auto gapOf = [&](const Eigen::VectorXd& a1, const Eigen::VectorXd& b1,
        const Eigen::VectorXd& a2, const Eigen::VectorXd& b2)
    {
        scalar sum = 0;
        label count = 0;
        for (label i = 0; i < n; ++i)
        {
            if (moves[i])
            {
                sum += a1(i)*b1(i);
                ++count;
                if (upper[i])
                {
                    sum += a2(i)*b2(i);
                    ++count;
                }
            }
        }
        return sum/max(count, label(1));
    };

    const label stallSteps = 10;
    scalar best = GREAT;
    label bestStep = 0;
    label step = 0;
    for (; step < interiorPointIterations_; ++step)
    {
        // The iterate clipped to its box (x - lo = s1 > 0 and hi - x = s2
        // > 0 up to round-off: w serves unless clipping moved it)
        const Eigen::VectorXd w(product(x) + b);
        const Eigen::VectorXd xc(x.cwiseMax(lo).cwiseMin(hi));
        const Eigen::VectorXd wc
        (
            xc == x ? w : Eigen::VectorXd(product(xc) + b)
        );
        const scalar v = violationOnScale(wc, lo, hi, xc, wScale);
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
                step - bestStep >= lcpSolver::loadScaleStallSteps
             && violationOnScale(wc, lo, hi, xc, bMax) <= tolerance_
            )
        )
        {
            // Stalled; or stalled on the load's scale with the tolerance
            // met on max |b| (round-off keeps the stricter one out of
            // reach: an island whose load is small against its apart
            // contacts' b)
            break;
        }

        // Residual r = A x + b - z1 + z2 of the moving variables
        Eigen::VectorXd r(Eigen::VectorXd::Zero(n));
        for (label i = 0; i < n; ++i)
        {
            if (moves[i])
            {
                r(i) = w(i) - z1(i) + (upper[i] ? z2(i) : 0);
                D(i) = z1(i)/s1(i) + (upper[i] ? z2(i)/s2(i) : 0);
            }
        }
        const scalar mu = gapOf(s1, z1, s2, z2);
        if (!factorise())
        {
            break;
        }

        // One Newton direction for the targets c1 = s1 z1 + dc1 (lower)
        // and c2 (upper) of the products: z_k s_k + ds_k z_k + s_k dz_k
        // = c_k, with ds1 = dx, ds2 = -dx, A dx - dz1 + dz2 = -r
        Eigen::VectorXd dx(n), dz1(n), dz2(n);
        auto direction =
        [&](const Eigen::VectorXd& c1, const Eigen::VectorXd& c2)
        {
            Eigen::VectorXd rhs(Eigen::VectorXd::Zero(n));
            for (label i = 0; i < n; ++i)
            {
                if (moves[i])
                {
                    rhs(i) =
                        -r(i) + c1(i)/s1(i) - (upper[i] ? c2(i)/s2(i) : 0);
                }
            }
            dx = solveNewton(rhs);
            dz1.setZero();
            dz2.setZero();
            for (label i = 0; i < n; ++i)
            {
                if (moves[i])
                {
                    dz1(i) = (c1(i) - z1(i)*dx(i))/s1(i);
                    if (upper[i])
                    {
                        dz2(i) = (c2(i) + z2(i)*dx(i))/s2(i);
                    }
                }
            }
        };

        // The largest step in (0, 1] that keeps s and z positive
        auto maxStep = [&]()
        {
            scalar alpha = 1;
            for (label i = 0; i < n; ++i)
            {
                if (!moves[i])
                {
                    continue;
                }
                if (dx(i) < 0)
                {
                    alpha = min(alpha, -s1(i)/dx(i));
                }
                if (dz1(i) < 0)
                {
                    alpha = min(alpha, -z1(i)/dz1(i));
                }
                if (upper[i])
                {
                    if (dx(i) > 0)
                    {
                        alpha = min(alpha, s2(i)/dx(i));
                    }
                    if (dz2(i) < 0)
                    {
                        alpha = min(alpha, -z2(i)/dz2(i));
                    }
                }
            }
            return alpha;
        };

        // Predictor (affine scaling): the products to zero
        const Eigen::VectorXd c1Aff(-s1.cwiseProduct(z1));
        const Eigen::VectorXd c2Aff(-s2.cwiseProduct(z2));
        direction(c1Aff, c2Aff);
        if (!dx.allFinite())
        {
            break;
        }
        const scalar alphaAff = maxStep();
        const scalar muAff = gapOf
        (
            s1 + alphaAff*dx, z1 + alphaAff*dz1,
            s2 - alphaAff*dx, z2 + alphaAff*dz2
        );
        const scalar sigma = pow3(muAff/max(mu, VSMALL));

        // Corrector: centring sigma mu and the second-order term
        const Eigen::VectorXd c1
        (
            (c1Aff - dx.cwiseProduct(dz1)).array() + sigma*mu
        );
        const Eigen::VectorXd c2
        (
            (c2Aff + dx.cwiseProduct(dz2)).array() + sigma*mu
        );
        direction(c1, c2);
        if (!dx.allFinite() || !dz1.allFinite() || !dz2.allFinite())
        {
            break;
        }
        const scalar alpha = min(scalar(1), 0.99*maxStep());
        for (label i = 0; i < n; ++i)
        {
            if (moves[i])
            {
                x(i) += alpha*dx(i);
                s1(i) += alpha*dx(i);
                z1(i) += alpha*dz1(i);
                if (upper[i])
                {
                    s2(i) -= alpha*dx(i);
                    z2(i) += alpha*dz2(i);
                }
            }
        }
    }
    x = x.cwiseMax(lo).cwiseMin(hi);
    return step;
}


Foam::rbd::lcpResult Foam::rbd::boxedBlockPivoting::solve
(
    const Eigen::SparseMatrix<double>& A,
    const lcpFactors& factors,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& lo,
    const Eigen::VectorXd& hi,
    std::vector<side>& sides,
    Eigen::VectorXd& x
) const
{
    autoPtr<lcpBodySpace> body;
    if (lcpBodySpace::pays(A, factors))
    {
        body.reset(new lcpBodySpace(factors));
    }
    return solve(A, body.get(), b, lo, hi, sides, x);
}


Foam::rbd::lcpResult Foam::rbd::boxedBlockPivoting::solve
(
    const Eigen::SparseMatrix<double>& A,
    lcpBodySpace* body,
    const Eigen::VectorXd& b,
    const Eigen::VectorXd& lo,
    const Eigen::VectorXd& hi,
    std::vector<side>& sides,
    Eigen::VectorXd& x,
    const bool exchanges
) const
{
    typedef Eigen::SparseMatrix<double> sparseMatrix;

    const label n = b.size();
    lcpResult result;
    x = Eigen::VectorXd::Zero(n);
    if
    (
        A.rows() != n || A.cols() != n || lo.size() != n || hi.size() != n
    )
    {
        FatalErrorInFunction
            << "Boxed LCP of inconsistent size: A is " << label(A.rows())
            << " x " << label(A.cols()) << ", b has " << n << ", lo "
            << label(lo.size()) << " and hi " << label(hi.size())
            << " entries" << nl
            << exit(FatalError);
    }
    if (n == 0)
    {
        result.converged = true;
        sides.clear();
        return result;
    }

    scalar diagMax = 0;
    bool finite = b.allFinite() && lo.allFinite();
    for (label j = 0; j < n && finite; ++j)
    {
        finite = lo(j) <= hi(j);
        for (sparseMatrix::InnerIterator it(A, j); it; ++it)
        {
            finite = finite && std::isfinite(it.value());
            if (it.row() == j)
            {
                diagMax = max(diagMax, it.value());
            }
        }
    }
    if (!finite || diagMax <= 0)
    {
        sides.assign(n, side::lower);
        x = lo;
        result.maxViolation = finite ? 0 : GREAT;
        result.converged = finite;
        return result;
    }
    const scalar eps = regularisation_*diagMax;
    const scalar bRef = b.cwiseAbs().maxCoeff();

    // A variable with lo = hi is fixed at its bound
    std::vector<bool> fixed(n);
    for (label i = 0; i < n; ++i)
    {
        fixed[i] = !(lo(i) < hi(i));
    }
    if (label(sides.size()) != n)
    {
        sides.assign(n, side::free);
    }
    for (label i = 0; i < n; ++i)
    {
        if (fixed[i])
        {
            sides[i] = side::lower;
        }
        else if (sides[i] == side::upper && !std::isfinite(hi(i)))
        {
            sides[i] = side::free;
        }
    }

    auto product = [&](const Eigen::VectorXd& y)
    {
        return body ? body->product(y) : Eigen::VectorXd(A*y);
    };

    Eigen::SimplicialLDLT
    <
        sparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>
    > ldlt;
    std::vector<label> pos(n), members, infeasible;
    activeSetSystem system;
    Eigen::VectorXd w(n), best(x);
    label fewestSoFar = n + 1;

    blockExchangeProgress progress(n);

    for (label iter = 0; exchanges && iter < maxIterations_; ++iter)
    {
        // The variables at their bounds, and the free ones
        Eigen::VectorXd xFixed(Eigen::VectorXd::Zero(n));
        members.clear();
        for (label i = 0; i < n; ++i)
        {
            pos[i] = -1;
            if (sides[i] == side::lower)
            {
                xFixed(i) = lo(i);
            }
            else if (sides[i] == side::upper)
            {
                xFixed(i) = hi(i);
            }
            else
            {
                pos[i] = members.size();
                members.push_back(i);
            }
        }
        Eigen::VectorXd rFull(-b);
        if (!xFixed.isZero(0))
        {
            rFull -= product(xFixed);
        }
        Eigen::VectorXd z;
        if
        (
            !solveActiveSet
            (
                A, body, members, pos, eps, rFull, ldlt, system, z
            )
        )
        {
            break;
        }
        x = xFixed + z;
        w = product(x) + b;
        result.iterations = iter + 1;

        const scalar xRef = x.cwiseAbs().maxCoeff();
        infeasible.clear();
        for (label i = 0; i < n; ++i)
        {
            bool bad = false;
            switch (sides[i])
            {
                case side::free:
                    bad =
                        x(i) < lo(i) - tolerance_*xRef
                     || x(i) > hi(i) + tolerance_*xRef;
                    break;
                case side::lower:
                    bad = !fixed[i] && w(i) < -tolerance_*bRef;
                    break;
                case side::upper:
                    bad = w(i) > tolerance_*bRef;
                    break;
            }
            if (bad)
            {
                infeasible.push_back(i);
            }
        }

        if (infeasible.empty())
        {
            // w_F = 0 up to round-off, unless A_FF x = r_F has no solution
            scalar wF = 0;
            for (const label i : members)
            {
                wF = max(wF, mag(w(i)));
            }
            result.converged = wF <= std::sqrt(tolerance_)*bRef;
        }

        // The candidate with the fewest infeasible variables, clipped to
        // its box, is returned if the exchanges do not converge
        const label nInfeasible = infeasible.size();
        if (nInfeasible < fewestSoFar)
        {
            fewestSoFar = nInfeasible;
            best = x.cwiseMax(lo).cwiseMin(hi);
        }
        if (infeasible.empty())
        {
            break;
        }

        if (!progress.proceed(nInfeasible))
        {
            // The block exchanges cycle
            break;
        }
        for (const label i : infeasible)
        {
            if (sides[i] != side::free)
            {
                sides[i] = side::free;
            }
            else
            {
                sides[i] = x(i) < lo(i) ? side::lower : side::upper;
            }
        }
    }

    // Without exchanges no candidate: the interior point's answer is
    // taken as it is (the measure is 0 for x = 0, so a zero candidate
    // could not be beaten)
    x = best;
    scalar bestViolation =
        exchanges ? violation(product(x) + b, b, lo, hi, x) : GREAT;
    result.converged = result.converged && bestViolation <= tolerance_;

    // Block exchanges cycled or ran out: the interior point, and the
    // sides of its answer for the next solve
    if (!result.converged && interiorPointIterations_ > 0)
    {
        Eigen::VectorXd xi;
        result.newtonSteps = interiorPoint(A, body, b, lo, hi, diagMax, xi);
        const Eigen::VectorXd wi(product(xi) + b);
        const scalar vi = violation(wi, b, lo, hi, xi);
        result.iterations += result.newtonSteps;
        if (vi < bestViolation)
        {
            x = xi;
            bestViolation = vi;
            const scalar xRef = max(xi.cwiseAbs().maxCoeff(), VSMALL);
            for (label i = 0; i < n; ++i)
            {
                const scalar toLo = (xi(i) - lo(i))/xRef;
                const scalar toHi = (hi(i) - xi(i))/xRef;
                sides[i] =
                    fixed[i] || (toLo < sqrt(tolerance_) && wi(i) > 0)
                  ? side::lower
                  : (toHi < sqrt(tolerance_) && wi(i) < 0)
                  ? side::upper
                  : side::free;
            }
        }
    }

    result.maxViolation = bestViolation;
    result.converged = bestViolation <= tolerance_;
    return result;
}


// ************************************************************************* //
