/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "restingContactSolver.H"
#include "collisionResolver.H"
#include "stateIO.H"
#include <algorithm>
#include <limits>
#include <Eigen/Dense>
#include <vector>
#include <cstdint>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;
    using namespace Foam::rbd;

    //- Acceleration of the material point at p of body b under force F and
    //  torque tau (eq 29)
    vector pointAcceleration
    (
        const rigidBody& b,
        const vector& F,
        const vector& tau,
        const point& p
    )
    {
        const vector r(p - b.x());
        const vector& w = b.omega();
        const vector wDot(b.applyInvInertia(tau - (w ^ b.L())));
        return b.invMass()*F + (wDot ^ r) + (w ^ (w ^ r));
    }

    //- Relative acceleration of i against k at the contact point
    vector relativeAcceleration
    (
        const contact& c,
        const UList<rigidBody>& bodies,
        const boolList& fixed,
        const UList<vector>& F,
        const UList<vector>& tau
    )
    {
        vector a(pointAcceleration(bodies[c.i], F[c.i], tau[c.i], c.p));
        if (c.k >= 0 && !fixed[c.k])
        {
            a -= pointAcceleration(bodies[c.k], F[c.k], tau[c.k], c.p);
        }
        return a;
    }

    //- Whether body b of contact c moves with the contact forces: i, and
    //  k where it is a pellet awake (as applyForce below)
    bool movedBy(const contact& c, const label b, const boolList& fixed)
    {
        return b == c.i || (b == c.k && b >= 0 && !fixed[b]);
    }

    //- Apply force f at the contact: +f to i, -f to k
    void applyForce
    (
        const contact& c,
        const vector& f,
        const UList<rigidBody>& bodies,
        const boolList& fixed,
        UList<vector>& F,
        UList<vector>& tau
    )
    {
        F[c.i] += f;
        tau[c.i] += ((c.p - bodies[c.i].x()) ^ f);
        if (c.k >= 0 && !fixed[c.k])
        {
            F[c.k] -= f;
            tau[c.k] -= ((c.p - bodies[c.k].x()) ^ f);
        }
    }

    //- Key of the pair of a contact, the same whichever body is i
    std::uint64_t pairKey(const contact& c)
    {
        const label a = max(c.i, c.k);
        const label b = min(c.i, c.k);
        return
            (std::uint64_t(std::uint32_t(a)) << 32)
          | std::uint32_t(b - label(tubeBottom));
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::restingContactSolver::restingContactSolver
(
    const dictionary& dict,
    const scalar compliance,
    const bool coupled,
    const label frictionRounds
)
:
    solver_(lcpSolver::New(dict)),
    boxed_(),
    assembly_(compliance),
    coupled_(coupled),
    frictionRounds_(frictionRounds),
    normalForces_(),
    active_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::restingContactSolver::bodyBuffers::resize(const label n)
{
    const label n0 = listed.size();
    if (n <= n0)
    {
        return;
    }
    listed.resize(n, false);
    for (List<vector>* f : {&Ffric, &tauFric, &Ftot, &tauTot})
    {
        f->setSize(n);
        for (label b = n0; b < n; ++b)
        {
            (*f)[b] = Zero;
        }
    }
}


Foam::rbd::restingContactSolver::result
Foam::rbd::restingContactSolver::solve
(
    const UList<rigidBody>& bodies,
    const UList<contact>& contacts,
    const boolList& fixed,
    const scalar h,
    UList<vector>& F,
    UList<vector>& tau
) const
{
    result res;
    res.contacts = contacts.size();
    normalForces_.setSize(contacts.size());
    normalForces_ = 0;
    if (contacts.empty())
    {
        return res;
    }

    // The bodies the contacts move, each once: the only entries of the
    // per-body buffers this solve uses (and restores at its end)
    buf_.resize(bodies.size());
    std::vector<label> moved;
    for (const contact& c : contacts)
    {
        for (const label b : {c.i, c.k})
        {
            if (movedBy(c, b, fixed) && !buf_.listed[b])
            {
                buf_.listed[b] = true;
                moved.push_back(b);
            }
        }
    }

    // Islands: contacts connected through bodies that move
    islands_.build(contacts, fixed, bodies.size());
    res.islands = islands_.size();

    bool anyFriction = false;
    for (const contact& c : contacts)
    {
        anyFriction = anyFriction || c.mu > 0;
    }

    // External forces (gravity): F and tau as given, unchanged until the
    // totals at the end; contact forces kept apart
    const UList<vector>& Fext = F;
    const UList<vector>& tauExt = tau;
    List<vector>& Ffric = buf_.Ffric;
    List<vector>& tauFric = buf_.tauFric;

    // Friction of each contact [N]
    List<vector> friction(contacts.size(), Zero);

    lcpFactors factors;
    std::vector<bool> guess;

    // Warm start: pairs active in the previous step (then in pass 1)
    std::unordered_map<std::uint64_t, bool>& active = active_;

    // A of constraint rows (contact, unit direction) and its factors
    // (lcpAssembly)
    auto assemble =
    [&](const std::vector<lcpAssembly::constraint>& dirs,
        Eigen::SparseMatrix<double>& A, Eigen::VectorXd& shift)
    {
        assembly_.assemble(bodies, contacts, fixed, dirs, A, shift, factors);
    };

    // B of a normal row: d'' without contact forces (eq 28), plus the
    // step term
    auto normalB =
    [&](const contact& c, const UList<vector>& Fb, const UList<vector>& tb)
    {
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
            // geometric error, h^2 |v_t|^2/(2 rho) per step, is left to
            // the overlap correction.
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
    };

    // The normal forces of island s's contacts for the forces Fb, tb; its
    // matrix assembled anew, or (assembled) as the first pass left it
    if (label(islandSystems_.size()) < islands_.size())
    {
        islandSystems_.resize(islands_.size());
    }
    auto solveIsland =
    [&](const label s, const UList<vector>& Fb, const UList<vector>& tb,
        Eigen::VectorXd& phi, const bool assembled)
    {
        const std::vector<label>& cs = islands_.contacts(s);
        const label n = cs.size();
        islandSystem& sys = islandSystems_[s];
        if (!assembled)
        {
            std::vector<std::pair<label, vector>> dirs(n);
            for (label a = 0; a < n; ++a)
            {
                dirs[a] = {cs[a], contacts[cs[a]].n};
            }
            assembly_.assemble
            (
                bodies, contacts, fixed, dirs, sys.A, sys.shift, sys.factors
            );
        }
        const Eigen::SparseMatrix<double>& A = sys.A;
        const Eigen::VectorXd& shift = sys.shift;

        Eigen::VectorXd B(n);
        for (label a = 0; a < n; ++a)
        {
            B(a) = normalB(contacts[cs[a]], Fb, tb);
        }

        // The active set to start from: the contacts that carried a force
        // in the previous solve (guess only: the solution does not depend
        // on it)
        guess.assign(n, false);
        for (label a = 0; a < n; ++a)
        {
            const auto it = active.find(pairKey(contacts[cs[a]]));
            guess[a] = it != active.end() ? it->second : B(a) < 0;
        }

        phi.resize(n);
        const lcpResult lr = solver_->solve(A, sys.factors, B, guess, phi);
        res.iterations += lr.iterations;
        res.converged = res.converged && lr.converged;
        res.maxViolation = max(res.maxViolation, lr.maxViolation);
        res.largestIsland = max(res.largestIsland, n);
        for (label a = 0; a < n; ++a)
        {
            phi(a) = max(phi(a), scalar(0));
        }
        // A solve that missed its tolerance but whose candidate violates
        // the LCP by less than lcpSolver::usableViolation is used as it
        // is: a degenerate island's best candidates stop a little above
        // the tolerance
        if
        (
            !lr.converged
         && !(lr.maxViolation <= lcpSolver::usableViolation)
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
    };

    // The normal forces and friction of an island of material contact
    // points, together (see the header): true if solved, then phi and
    // the friction of its contacts are in phiAll and friction
    auto solveCoupled =
    [&](const std::vector<label>& cs, List<scalar>& phiAll)
    {
        const label nc = cs.size();

        // Rows: the normal of each contact, and two tangents where it has
        // friction, t1 against its slip at the end of the step under the
        // frictionless forces of pass 1 (so that where the contact slides
        // the box of the two gives mu phi against the slip, as Coulomb's
        // cone does). Ftot: the external forces with them, on the
        // island's bodies
        List<vector>& Ftot = buf_.Ftot;
        List<vector>& tauTot = buf_.tauTot;
        for (const label ci : cs)
        {
            const contact& c = contacts[ci];
            for (const label b : {c.i, c.k})
            {
                if (movedBy(c, b, fixed))
                {
                    Ftot[b] = Fext[b];
                    tauTot[b] = tauExt[b];
                }
            }
        }
        for (const label ci : cs)
        {
            applyForce
            (
                contacts[ci], phiAll[ci]*contacts[ci].n, bodies, fixed,
                Ftot, tauTot
            );
        }
        std::vector<std::pair<label, vector>> dirs;
        std::vector<label> normalRow(nc);
        std::vector<label> tangentRow(nc, -1);

        // Per contact with friction: the relative velocity v0 the step
        // starts with, and the relative acceleration under the external
        // forces alone (the tangent rows' B below)
        std::vector<vector> v0(nc, Zero);
        std::vector<vector> aExt(nc, Zero);
        for (label a = 0; a < nc; ++a)
        {
            const contact& c = contacts[cs[a]];
            normalRow[a] = dirs.size();
            dirs.emplace_back(cs[a], c.n);
            if (c.mu > 0)
            {
                v0[a] = collisionResolver::relativeVelocity(c, bodies, fixed);
                aExt[a] = relativeAcceleration(c, bodies, fixed, Fext, tauExt);
                const vector vEnd
                (
                    v0[a]
                  + h*relativeAcceleration(c, bodies, fixed, Ftot, tauTot)
                );
                vector t1(vEnd - (vEnd & c.n)*c.n);
                if (mag(t1) <= SMALL*mag(vEnd) || mag(t1) < VSMALL)
                {
                    // No slip: any tangent (the friction is free in both)
                    const vector axis
                    (
                        mag(c.n.x()) < 0.6 ? vector(1, 0, 0)
                      : vector(0, 1, 0)
                    );
                    t1 = axis - (axis & c.n)*c.n;
                }
                // Friction opposes the slip
                t1 /= -mag(t1);
                tangentRow[a] = dirs.size();
                dirs.emplace_back(cs[a], t1);
                dirs.emplace_back(cs[a], (c.n ^ t1));
            }
        }
        const label n = dirs.size();
        Eigen::VectorXd x(Eigen::VectorXd::Zero(n));
        for (label a = 0; a < nc; ++a)
        {
            x(normalRow[a]) = phiAll[cs[a]];
        }
        std::vector<boxedBlockPivoting::side> sides
        (
            n, boxedBlockPivoting::side::free
        );
        for (label a = 0; a < nc; ++a)
        {
            if (x(normalRow[a]) <= 0)
            {
                sides[normalRow[a]] = boxedBlockPivoting::side::lower;
            }
        }

        Eigen::SparseMatrix<double> A;
        Eigen::VectorXd shift;
        assemble(dirs, A, shift);
        autoPtr<lcpBodySpace> body;
        if (lcpBodySpace::pays(A, factors))
        {
            body.reset(new lcpBodySpace(factors));
        }

        // B: the normal rows as in solveIsland. A tangent row asks for the
        // slip v1 = -beta v0 at the end of the step, t . (a_rel + (1 +
        // beta) v_rel/h): beta = 0 stops the slip, which is dissipative
        // where the friction opposes the slip v0 the step starts with; a
        // contact whose friction points along v0 (f . v0 > 0) gets beta =
        // 1 in the next round: zero displacement over the step, v1 = -v0,
        // and no work (midpoint rule, constant force: the work is f . (v0
        // + v1) h/2)
        std::vector<scalar> beta(nc, 0);
        Eigen::VectorXd B(n);
        auto setB = [&]()
        {
            for (label a = 0; a < nc; ++a)
            {
                const contact& c = contacts[cs[a]];
                B(normalRow[a]) = normalB(c, Fext, tauExt);
                if (tangentRow[a] >= 0)
                {
                    const vector target(aExt[a] + (1 + beta[a])*v0[a]/h);
                    for (label k = 0; k < 2; ++k)
                    {
                        const label r = tangentRow[a] + k;
                        B(r) = (dirs[r].second & target);
                    }
                }
            }
        };

        // Rounds: the friction bounds |f_t1|, |f_t2| <= mu phi (a box,
        // t1 along the predicted slip: where the contact slides its
        // friction is mu phi along t1) for the normal forces of the round
        // before (pass 1 first), and beta as above. Done when no beta
        // changes and the normal force of every contact whose friction
        // is at a bound moved by less than frictionBoundTolerance
        const scalar inf = std::numeric_limits<scalar>::infinity();
        Eigen::VectorXd lo(Eigen::VectorXd::Zero(n));
        Eigen::VectorXd hi(Eigen::VectorXd::Constant(n, inf));
        std::vector<scalar> limitUsed(nc, 0);
        bool settled = false;
        label round = 0;
        for (; round < frictionRounds_ && !settled; ++round)
        {
            setB();
            for (label a = 0; a < nc; ++a)
            {
                const label r = tangentRow[a];
                if (r >= 0)
                {
                    limitUsed[a] = contacts[cs[a]].mu*x(normalRow[a]);
                    for (label k = 0; k < 2; ++k)
                    {
                        lo(r + k) = -limitUsed[a];
                        hi(r + k) = limitUsed[a];
                    }
                }
            }

            const lcpResult lr =
                boxed_.solve(A, body.get(), B, lo, hi, sides, x);
            res.iterations += lr.iterations;
            if (!(lr.maxViolation <= lcpSolver::usableViolation))
            {
                return false;
            }

            settled = true;
            for (label a = 0; a < nc; ++a)
            {
                const label r = tangentRow[a];
                if (r < 0)
                {
                    continue;
                }
                const vector f
                (
                    x(r)*dirs[r].second + x(r + 1)*dirs[r + 1].second
                );
                if (beta[a] == 0 && (f & v0[a]) > 0)
                {
                    beta[a] = 1;
                    settled = false;
                }
                const scalar limit = contacts[cs[a]].mu*x(normalRow[a]);
                const bool atBound =
                    sides[r] != boxedBlockPivoting::side::free
                 || sides[r + 1] != boxedBlockPivoting::side::free;
                if
                (
                    (atBound || mag(f) > limit)
                 && mag(limit - limitUsed[a])
                  > frictionBoundTolerance*limitUsed[a] + VSMALL
                )
                {
                    settled = false;
                }
            }
        }
        res.largestIsland = max(res.largestIsland, n);

        // The last round's solution as it is: its friction lies in the
        // box of the normal forces of the round before
        for (label a = 0; a < nc; ++a)
        {
            const label ci = cs[a];
            phiAll[ci] = max(x(normalRow[a]), scalar(0));
            friction[ci] = Zero;
            if (tangentRow[a] >= 0)
            {
                const label r = tangentRow[a];
                friction[ci] =
                    x(r)*dirs[r].second + x(r + 1)*dirs[r + 1].second;
            }
        }
        return true;
    };

    // Pass 1: normal forces without friction
    List<scalar> phiAll(contacts.size(), scalar(0));
    for (label s = 0; s < islands_.size(); ++s)
    {
        Eigen::VectorXd phi;
        const std::vector<label>& island = islands_.contacts(s);
        solveIsland(s, Fext, tauExt, phi, false);
        for (size_t a = 0; a < island.size(); ++a)
        {
            phiAll[island[a]] = phi(a);
        }
    }

    auto recordActive = [&]()
    {
        active.clear();
        forAll(contacts, ci)
        {
            bool& a = active[pairKey(contacts[ci])];
            a = a || phiAll[ci] > 0;
        }
    };
    recordActive();

    if (anyFriction)
    {
        // Islands of material contact points (mesh pellets, cylinders and
        // rings against the tube): normal forces and friction in one
        // solve. The others (spheres, whose forces all point through
        // their centres), and a coupled solve that fails: friction for the
        // frictionless normal forces, then the normal forces again
        std::vector<bool> staggered(contacts.size(), false);
        std::vector<label> staggeredIslands;
        for (label s = 0; s < islands_.size(); ++s)
        {
            const std::vector<label>& island = islands_.contacts(s);
            bool material = true;
            bool withFriction = false;
            for (const label ci : island)
            {
                material = material && !contacts[ci].centreBased;
                withFriction = withFriction || contacts[ci].mu > 0;
            }
            if (!withFriction)
            {
                continue;
            }
            if (coupled_ && material && solveCoupled(island, phiAll))
            {
                for (const label ci : island)
                {
                    applyForce
                    (
                        contacts[ci], friction[ci], bodies, fixed,
                        Ffric, tauFric
                    );
                }
                continue;
            }
            staggeredIslands.push_back(s);
            for (const label ci : island)
            {
                staggered[ci] = true;
            }
        }

        // The staggered solve, for the islands that need it
        if (!staggeredIslands.empty())
        {
            // Friction from the predicted slip at the end of the step, clamped
            // to mu phi (eq 9); two Gauss-Seidel sweeps for coupled contacts
            List<vector>& Ftot = buf_.Ftot;
            List<vector>& tauTot = buf_.tauTot;
            for (const label b : moved)
            {
                Ftot[b] = Fext[b];
                tauTot[b] = tauExt[b];
            }
            forAll(contacts, ci)
            {
                if (staggered[ci])
                {
                    applyForce
                    (
                        contacts[ci], phiAll[ci]*contacts[ci].n, bodies, fixed,
                        Ftot, tauTot
                    );
                }
            }

            for (label sweep = 0; sweep < 2; ++sweep)
            {
                forAll(contacts, ci)
                {
                    const contact& c = contacts[ci];
                    const scalar limit = c.mu*phiAll[ci];
                    if (!staggered[ci] || limit <= 0)
                    {
                        continue;
                    }
                    vector& f = friction[ci];

                    // Remove this contact's friction, then predict the slip
                    applyForce(c, -f, bodies, fixed, Ftot, tauTot);
                    applyForce(c, -f, bodies, fixed, Ffric, tauFric);

                    const vector vRel
                    (
                        collisionResolver::relativeVelocity(c, bodies, fixed)
                      + h*relativeAcceleration(c, bodies, fixed, Ftot, tauTot)
                    );
                    const vector vt(vRel - (vRel & c.n)*c.n);
                    const scalar slip = mag(vt);

                    f = Zero;
                    if (slip > VSMALL)
                    {
                        const vector t(-vt/slip);
                        const scalar fStop =
                            slip
                           /(h*collisionResolver::effectiveInvMass
                            (
                                c, t, bodies, fixed
                            ));
                        f = min(limit, fStop)*t;
                    }

                    applyForce(c, f, bodies, fixed, Ftot, tauTot);
                    applyForce(c, f, bodies, fixed, Ffric, tauFric);
                }
            }

            // Pass 2: normal forces with friction in B
            List<vector>& Fb = buf_.Ftot;
            List<vector>& tb = buf_.tauTot;
            for (const label b : moved)
            {
                Fb[b] = Fext[b] + Ffric[b];
                tb[b] = tauExt[b] + tauFric[b];
            }
            for (const label s : staggeredIslands)
            {
                Eigen::VectorXd phi;
                const std::vector<label>& island = islands_.contacts(s);
                solveIsland(s, Fb, tb, phi, true);
                for (size_t a = 0; a < island.size(); ++a)
                {
                    phiAll[island[a]] = phi(a);
                }
            }
        }
    }

    recordActive();

    // Total: external + friction + normal (the friction is zero on a body
    // no contact moves)
    for (const label b : moved)
    {
        F[b] = Fext[b] + Ffric[b];
        tau[b] = tauExt[b] + tauFric[b];
    }
    forAll(contacts, ci)
    {
        applyForce
        (
            contacts[ci], phiAll[ci]*contacts[ci].n, bodies, fixed, F, tau
        );
    }
    normalForces_ = phiAll;

    // The buffers as between solves
    islands_.clear();
    for (const label b : moved)
    {
        Ffric[b] = Zero;
        tauFric[b] = Zero;
        buf_.listed[b] = false;
    }

    return res;
}


void Foam::rbd::restingContactSolver::writeState(stateWriter& out) const
{
    // In key order: the same state gives the same file
    std::vector<std::pair<std::uint64_t, bool>> pairs
    (
        active_.begin(), active_.end()
    );
    std::sort(pairs.begin(), pairs.end());
    out.put(label(pairs.size()));
    for (const auto& p : pairs)
    {
        out.put(p.first).put(p.second);
    }
}


void Foam::rbd::restingContactSolver::readState(stateReader& in)
{
    label n = 0;
    in.get(n);
    in.checkSize(n);
    active_.clear();
    for (label a = 0; a < n; ++a)
    {
        std::uint64_t key = 0;
        bool on = false;
        in.get(key).get(on);
        active_[key] = on;
    }
}


// ************************************************************************* //
