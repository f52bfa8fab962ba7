/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "restingContactSolver.H"
#include "staggeredFriction.H"
#include "stateIO.H"
#include <algorithm>
#include <vector>
#include <cstdint>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::restingContactSolver::restingContactSolver
(
    const dictionary& dict,
    const scalar compliance,
    const scalar band,
    const bool coupled,
    const label frictionRounds
)
:
    solver_(lcpSolver::New(dict)),
    assembly_(compliance),
    coupled_(coupled),
    coupledSolve_(frictionRounds),
    normalForces_(),
    active_(),
    band_(band)
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


void Foam::rbd::restingContactSolver::normalPass
(
    const restingProblem& problem,
    const label s,
    const UList<vector>& Fb,
    const UList<vector>& tb,
    const bool assembled,
    List<scalar>& phiAll,
    result& res
) const
{
    const std::vector<label>& island = islands_.contacts(s);
    Eigen::VectorXd phi;
    normalRows_.solve
    (
        problem, s, island, Fb, tb, assembled, assembly_, *solver_, active_,
        normalExchanges_, res, phi
    );
    for (size_t a = 0; a < island.size(); ++a)
    {
        phiAll[island[a]] = phi(a);
    }
}


void Foam::rbd::restingContactSolver::frictionStage
(
    const restingProblem& problem,
    const std::vector<label>& moved,
    const UList<vector>& Fext,
    const UList<vector>& tauExt,
    List<scalar>& phiAll,
    result& res
) const
{
    const UList<rigidBody>& bodies = problem.bodies;
    const UList<contact>& contacts = problem.contacts;
    const boolList& fixed = problem.fixed;
    List<vector>& Ffric = buf_.Ffric;
    List<vector>& tauFric = buf_.tauFric;

    // Friction of each contact [N]
    List<vector> friction(contacts.size(), Zero);

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
        if
        (
            coupled_ && material
         && coupledSolve_.solve
            (
                problem, island, Fext, tauExt, buf_.Ftot, buf_.tauTot,
                assembly_, boxedExchanges_, phiAll, friction, res
            )
        )
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
        // Friction from the predicted slip at the end of the step,
        // clamped to mu phi (eq 9)
        staggeredFriction
        (
            problem, staggered, moved, phiAll, Fext, tauExt,
            buf_.Ftot, buf_.tauTot, Ffric, tauFric, friction
        );

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
            normalPass(problem, s, Fb, tb, true, phiAll, res);
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

    // The contacts' points recorded by the last solve
    active_.match(bodies, contacts, band_);

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

    const restingProblem problem{bodies, contacts, fixed, h};

    // Pass 1: normal forces without friction, warm-started from the pairs
    // active in the previous step; then those of pass 1 are the guess of
    // pass 2
    normalRows_.resize(islands_.size());
    List<scalar> phiAll(contacts.size(), scalar(0));
    for (label s = 0; s < islands_.size(); ++s)
    {
        normalPass(problem, s, Fext, tauExt, false, phiAll, res);
    }
    active_.record(bodies, contacts, phiAll);

    if (anyFriction)
    {
        frictionStage(problem, moved, Fext, tauExt, phiAll, res);
    }
    active_.record(bodies, contacts, phiAll);

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
    const warmStart::entryList& pairs = active_.entries();
    out.put(label(pairs.size()));
    for (const auto& p : pairs)
    {
        out.put(p.first).put(p.second);
    }
    const warmStart::pointList& points = active_.points();
    out.put(label(points.size()));
    for (const warmStart::contactPoint& p : points)
    {
        out.put(p.key).put(p.body).put(p.local).put(p.active);
    }
    for (const exchangeRecord* r : {&normalExchanges_, &boxedExchanges_})
    {
        out.put(r->share()).put(r->skipped());
    }
}


void Foam::rbd::restingContactSolver::readState(stateReader& in)
{
    label n = 0;
    in.get(n);
    in.checkSize(n);
    warmStart::entryList pairs(n);
    for (auto& p : pairs)
    {
        in.get(p.first).get(p.second);
    }
    in.get(n);
    in.checkSize(n);
    warmStart::pointList points(n);
    for (warmStart::contactPoint& p : points)
    {
        in.get(p.key).get(p.body).get(p.local).get(p.active);
    }
    active_.set(pairs, points);
    for (exchangeRecord* r : {&normalExchanges_, &boxedExchanges_})
    {
        scalar share = 0;
        label skipped = 0;
        in.get(share).get(skipped);
        r->set(share, skipped);
    }
}


// ************************************************************************* //
