/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "coupledFriction.H"
#include "normalRows.H"
#include "collisionResolver.H"
#include "lcpBodySpace.H"

#include <limits>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::coupledFriction::coupledFriction(const label rounds)
:
    boxed_(),
    rounds_(rounds)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::coupledFriction::makeRows
(
    const restingProblem& p,
    const std::vector<label>& cs,
    const UList<vector>& Fext,
    const UList<vector>& tauExt,
    UList<vector>& Ftot,
    UList<vector>& tauTot,
    const List<scalar>& phiAll,
    islandRows& rows
)
{
    const UList<rigidBody>& bodies = p.bodies;
    const UList<contact>& contacts = p.contacts;
    const boolList& fixed = p.fixed;
    const scalar h = p.h;
    const label nc = cs.size();

    // Rows: the normal of each contact, and two tangents where it has
    // friction, t1 against its slip at the end of the step under the
    // frictionless forces of pass 1 (so that where the contact slides
    // the box of the two gives mu phi against the slip, as Coulomb's
    // cone does). Ftot: the external forces with them, on the
    // island's bodies
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
    std::vector<std::pair<label, vector>>& dirs = rows.dirs;
    std::vector<label>& normalRow = rows.normalRow;
    std::vector<label>& tangentRow = rows.tangentRow;
    dirs.clear();
    normalRow.assign(nc, 0);
    tangentRow.assign(nc, -1);

    // Per contact with friction: the relative velocity v0 the step
    // starts with, and the relative acceleration under the external
    // forces alone (the tangent rows' B below)
    std::vector<vector>& v0 = rows.v0;
    std::vector<vector>& aExt = rows.aExt;
    v0.assign(nc, Zero);
    aExt.assign(nc, Zero);
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
}


bool Foam::rbd::coupledFriction::solve
(
    const restingProblem& p,
    const std::vector<label>& cs,
    const UList<vector>& Fext,
    const UList<vector>& tauExt,
    UList<vector>& Ftot,
    UList<vector>& tauTot,
    lcpAssembly& assembly,
    exchangeRecord& record,
    List<scalar>& phiAll,
    List<vector>& friction,
    restingSolveResult& res
) const
{
    const UList<rigidBody>& bodies = p.bodies;
    const UList<contact>& contacts = p.contacts;
    const boolList& fixed = p.fixed;
    const scalar h = p.h;
    const label nc = cs.size();

    // The rows and the slips they act against
    islandRows rows;
    makeRows(p, cs, Fext, tauExt, Ftot, tauTot, phiAll, rows);
    const std::vector<std::pair<label, vector>>& dirs = rows.dirs;
    const std::vector<label>& normalRow = rows.normalRow;
    const std::vector<label>& tangentRow = rows.tangentRow;
    const std::vector<vector>& v0 = rows.v0;
    const std::vector<vector>& aExt = rows.aExt;

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
    lcpFactors factors;
    // In body space the boxed solve reads A's diagonal only
    assembly.assemble
    (
        bodies, contacts, fixed, dirs, A, shift, factors,
        lcpAssembly::entries::diagonalInBodySpace
    );
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
            B(normalRow[a]) = normalRows::normalB(p, c, Fext, tauExt);
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
    // On an island of at least interiorPointBodies moving bodies, once
    // the exchanges of a round cycle and the interior point answers, the
    // later rounds go to the interior point at once: there the exchanges
    // of such a round converged on 0-6 % of the problems, 0.0 % on a
    // 100-cylinder heap, against 5-50 % on islands of 1-8 bodies
    // (docs/restingSolveCost.md, "Twenty-third session")
    const bool large = assembly.movingBodies() >= interiorPointBodies;
    // Its first round tries the exchanges first only where they have been
    // converging on such islands (exchangeRecord)
    bool exchanges = !large || record.tryExchanges();
    const bool tracked = large && exchanges;
    // Such an island takes at most largeIslandRounds rounds: on a
    // 100-cylinder heap its rounds never settle (the redundant contacts'
    // normal forces shift from round to round), the friction above mu
    // phi of the round's own normal forces grew from 3.0 % of sum(mu
    // phi) after the first round to 6.4, 8.3 and 7.9 % after the next
    // three, and only the energy-adding friction (beta) fell, from 1.1 %
    // of the friction's power to 0.6 % after two rounds and 0.2 % after
    // four (docs/restingSolveCost.md, "Twenty-fourth session")
    const label roundsHere =
        large ? min(rounds_, largeIslandRounds) : rounds_;
    for (; round < roundsHere && !settled; ++round)
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
            boxed_.solve(A, body.get(), B, lo, hi, sides, x, exchanges);
        res.iterations += lr.iterations;
        if (round == 0 && tracked)
        {
            record.record(lr.newtonSteps == 0);
        }
        exchanges = exchanges && (lr.newtonSteps == 0 || !large);
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
    res.frictionRounds = max(res.frictionRounds, round);

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
}


// ************************************************************************* //
