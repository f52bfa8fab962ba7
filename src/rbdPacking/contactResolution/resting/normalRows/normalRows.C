/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "normalRows.H"
#include "collisionResolver.H"
#include "coupledFriction.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::normalRows::normalB
(
    const restingProblem& p,
    const contact& c,
    const UList<vector>& Fb,
    const UList<vector>& tb
)
{
    const UList<rigidBody>& bodies = p.bodies;
    const boolList& fixed = p.fixed;
    const scalar h = p.h;
    const vector vRel
    (
        collisionResolver::relativeVelocity(c, bodies, fixed)
    );
    const scalar vn = vRel & c.n;
    scalar ddGap;
    if (c.centreBased)
    {
        // Gap between centres (spheres): the linear part n . (a_i -
        // a_k) of d''. The curvature part n' . (v_i - v_k) is left
        // out on purpose: with it, a pellet sliding along the
        // concave tube wall would let the wall force do positive
        // work; without it the work of every contact force over a
        // step is -phi max(d, 0) <= 0 (see the header). Its
        // geometric error, h^2 |v_t|^2/(2 rho) per step, closes the
        // gap only on the concave wall (rho = R - a), where the step
        // holds it to half the touching gap for accelerations along
        // the wall up to g (stepControl); the overlap correction takes
        // what is left.
        vector aC(bodies[c.i].invMass()*Fb[c.i]);
        if (c.k >= 0 && !fixed[c.k])
        {
            aC -= bodies[c.k].invMass()*Fb[c.k];
        }
        ddGap = (c.n & aC);
    }
    else
    {
        // Material contact points (eq 28)
        const vector aRel
        (
            relativeAcceleration(c, bodies, fixed, Fb, tb)
        );
        ddGap = (c.n & aRel) + 2*(c.nDot & vRel);
        if (c.rhoI != 0 || c.rhoK != 0)
        {
            // Points that slide over round features (contact.H)
            vector wRel(bodies[c.i].omega());
            if (c.k >= 0 && !fixed[c.k])
            {
                wRel -= bodies[c.k].omega();
            }
            const vector wPerp(wRel - (wRel & c.n)*c.n);
            auto round = [&](const vector& a, const scalar rho)
            {
                if (rho == 0)
                {
                    return scalar(0);
                }
                // cos^2 of the feature plane's tilt to n, at least
                // 0.02^2: a face lying flat is held by its corners
                const scalar cc = max(1 - sqr(c.n & a), 4e-4);
                const scalar sDot = (wRel & (a ^ c.n));
                return rho/cc*(sqr(sDot)/cc - magSqr(wPerp));
            };
            ddGap += round(c.axisI, c.rhoI) + round(c.axisK, c.rhoK);
        }
    }
    return ddGap + 2*(max(c.gap, scalar(0)) + h*vn)/sqr(h);
}


void Foam::rbd::normalRows::resize(const label n)
{
    if (label(systems_.size()) < n)
    {
        systems_.resize(n);
    }
}


void Foam::rbd::normalRows::solve
(
    const restingProblem& p,
    const label s,
    const std::vector<label>& cs,
    const UList<vector>& Fb,
    const UList<vector>& tb,
    const bool assembled,
    lcpAssembly& assembly,
    const lcpSolver& solver,
    const warmStart& active,
    exchangeRecord& record,
    restingSolveResult& res,
    Eigen::VectorXd& phi
)
{
    const UList<contact>& contacts = p.contacts;
    const label n = cs.size();
    islandSystem& sys = systems_[s];
    if (!assembled)
    {
        std::vector<std::pair<label, vector>> dirs(n);
        for (label a = 0; a < n; ++a)
        {
            dirs[a] = {cs[a], contacts[cs[a]].n};
        }
        assembly.assemble
        (
            p.bodies, contacts, p.fixed, dirs, sys.A, sys.shift, sys.factors
        );
    }
    if (!sys.kept)
    {
        sys.kept.reset(new activeSetFactor());
    }
    if (!assembled)
    {
        sys.kept->invalidate();

        // Candidates from the last factor (activeSetUpdate) on islands of
        // sphere contacts only: there they paid (500 placed spheres, seeds
        // 1-7: 0.84 times the CPU time); on 40 placed exact cylinders,
        // seeds 1-8, they bought nothing (1.06 times) and the trajectories
        // they changed gave one bed of eight over 0.5 % d
        // (docs/restingSolveCost.md, "Thirty-third session")
        bool centreBased = true;
        for (const label ci : cs)
        {
            centreBased = centreBased && contacts[ci].centreBased;
        }
        sys.kept->updates = centreBased;
    }
    const Eigen::SparseMatrix<double>& A = sys.A;
    const Eigen::VectorXd& shift = sys.shift;

    Eigen::VectorXd B(n);
    for (label a = 0; a < n; ++a)
    {
        B(a) = normalB(p, contacts[cs[a]], Fb, tb);
    }

    // The active set to start from: the contacts that carried a force
    // in the previous solve (warmStart: a guess)
    std::vector<bool>& guess = guess_;
    guess.assign(n, false);
    for (label a = 0; a < n; ++a)
    {
        guess[a] = active.guess(cs[a], contacts[cs[a]], B(a) < 0);
    }

    // On a large island, the block exchanges first only where they have
    // been converging (exchangeRecord)
    const bool tracked =
        !assembled
     && assembly.movingBodies() >= coupledFriction::interiorPointBodies;
    const bool exchanges = !tracked || record.tryExchanges();
    phi.resize(n);
    const lcpResult lr =
        solver.solve(A, sys.factors, B, guess, phi, *sys.kept, exchanges);
    if (tracked && exchanges)
    {
        record.record(lr.converged && lr.newtonSteps == 0);
    }
    res.iterations += lr.iterations;
    res.converged = res.converged && lr.converged;
    res.maxViolation = max(res.maxViolation, lr.maxViolation);
    res.largestIsland = max(res.largestIsland, n);
    for (label a = 0; a < n; ++a)
    {
        phi(a) = max(phi(a), scalar(0));
    }
    // A solve that missed its tolerance but whose candidate violates
    // the LCP by less than lcpSolver::clampViolation is used as it
    // is: a degenerate island's best candidates stop a little above
    // the tolerance
    if
    (
        !lr.converged
     && !(lr.maxViolation <= lcpSolver::clampViolation)
    )
    {
        // No solution (an infeasible island: bodies jammed between
        // contacts that accelerate into each other, or a solver that
        // ran out of iterations far from one): its forces may be
        // arbitrarily large and would launch pellets through their
        // neighbours. Each force is clamped to what its contact needs
        // on its own, -B_a/A_aa, so the step stays bounded: a loaded
        // stack may sink for the step, which the overlap correction
        // and the next solve repair.
        for (label a = 0; a < n; ++a)
        {
            const scalar Aaa = A.coeff(a, a) - shift(a);
            phi(a) = Aaa > 0 ? min(phi(a), max(-B(a), 0.0)/Aaa) : 0;
        }
    }
}


// ************************************************************************* //
