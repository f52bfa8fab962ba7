/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "world.H"
#include "stateIO.H"
#include "midpointIntegrator.H"
#include <algorithm>
#include <omp.h>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#include <Eigen/Core>
#pragma GCC diagnostic pop

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::world::world
(
    const tube& container,
    const pelletShape& shape,
    const pelletMaterial& material,
    const bool rotates,
    const simulationControls& controls
)
:
    tube_(container),
    shape_(shape),
    controls_(controls),
    material_(material),
    rotates_(rotates),
    rb_(shape.boundingRadius()),
    band_(controls.proximity*shape.boundingRadius()),
    touch_(controls.contactTolerance*shape.diameter()),
    projection_(controls.overlapSlop*shape.diameter(), rb_),
    dispatch_
    (
        shape, container, material.restitution, material.friction, band_,
        controls.contactModel, controls.threads
    ),
    stepControl_
    (
        controls.gravity, controls.restingVelocity, band_, touch_, rb_,
        contactDispatch::pairModel(shape, controls.contactModel) == "sphere",
        contactDispatch::pairModel(shape, controls.contactModel) == "prism",
        container.radius()
    ),
    sweep_
    (
        controls.sweepSpeed, touch_, band_, stepControl_.unseenClosing(),
        rb_,
        contactDispatch::pairModel(shape, controls.contactModel) == "sphere",
        container.radius()
    ),
    swept_(),
    sweptStart_(),
    held_(),
    bodyBound_(),
    restingContacts_(),
    sweepNear_(),
    sweepNearContainer_(false),
    sweepContacts_(),
    bodies_(),
    fixed_(),
    sleep_
    (
        controls.sleepVelocity, controls.sleepTime, rb_, band_, rotates,
        shape.isSphere()
    ),
    neighbours_(controls.neighbourSkin*shape.boundingRadius()),
    awake_(),
    activePairs_(),
    awakeValid_(false),
    activePairsBuild_(-1),
    collisions_
    (
        controls.restingVelocity,
        controls.slipVelocity,
        controls.restitutionSweeps,
        controls.maxSweeps,
        controls.collisionTolerance,
        controls.wakeVelocity
    ),
    resting_
    (
        controls.dict, controls.restingCompliance, band_,
        controls.restingFriction == "coupled", controls.frictionRounds
    ),
    rolling_(material.rollingFriction, 0.5*shape.diameter()),
    contacts_(),
    F_(),
    tau_(),
    time_(0),
    stats_(),
    tinySteps_(0)
{
    // Eigen, built with OpenMP, runs its larger products (row-major
    // sparse times dense above 20 000 nonzeros, dense GEMM) on all OpenMP
    // threads unless told: held to simulation/threads, so that threads 1
    // runs on one core. (No product in src/ is of those kinds today:
    // lcpBodySpace works by 6 x 6 blocks of its own)
    Eigen::setNbThreads(controls.threads);

    Info<< "Narrow phase (contactModel " << controls.contactModel << "): ";
    dispatch_.describe(Info);
    if (!dispatch_.spheres())
    {
        Info<< "; pellet pairs on " << controls.threads << " thread"
            << (controls.threads > 1 ? "s" : "");
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::rbd::world::addBody(const point& x, const quaternion& q)
{
    const scalar m = material_.density*shape_.volume();
    const vector I = material_.density*shape_.principalInertiaPerDensity();

    bodies_.append(rigidBody(m, I, x, q, rotates_));
    fixed_.append(false);
    sleep_.addBody(x, q);
    sleepSetChanged();
    return bodies_.size() - 1;
}


const Foam::UList<Foam::label>& Foam::rbd::world::awake() const
{
    if (!awakeValid_)
    {
        awake_.clear();
        forAll(fixed_, i)
        {
            if (!fixed_[i])
            {
                awake_.append(i);
            }
        }
        awakeValid_ = true;
        activePairsBuild_ = -1;
    }
    return awake_;
}


const Foam::UList<Foam::labelPair>& Foam::rbd::world::activePairs() const
{
    awake();
    if (activePairsBuild_ != neighbours_.nBuilds())
    {
        // The listed pairs with a body awake, from the neighbours of the
        // awake bodies (each pair once), in the order of pairs()
        const neighbourList::adjacencyList& adjacency =
            neighbours_.adjacency();
        activePairs_.clear();
        for (const label i : awake_)
        {
            if (i >= adjacency.size())
            {
                continue;
            }
            for (const label k : adjacency[i])
            {
                if (k > i)
                {
                    activePairs_.append(labelPair(i, k));
                }
                else if (fixed_[k])
                {
                    activePairs_.append(labelPair(k, i));
                }
            }
        }
        std::sort(activePairs_.begin(), activePairs_.end());
        activePairsBuild_ = neighbours_.nBuilds();
    }
    return activePairs_;
}


void Foam::rbd::world::setVelocity
(
    const label i,
    const vector& v,
    const vector& omega
)
{
    rigidBody& b = bodies_[i];
    // L = I omega with I = (I^-1)^-1 in the world frame
    const vector L = rotates_ ? (inv(b.invInertia()) & omega) : vector::zero;
    b.setState(b.x(), b.q(), b.mass()*v, L);
    wake(i);
}


void Foam::rbd::world::pelletPair
(
    const labelPair& pr,
    DynamicList<contact>& found,
    const label thread
) const
{
    // The awake body first where one sleeps
    label i = pr.first();
    label k = pr.second();
    if (fixed_[i] && !fixed_[k])
    {
        std::swap(i, k);
    }
    dispatch_.pelletPair(i, bodies_[i], k, bodies_[k], found, thread);
}


void Foam::rbd::world::pelletContainer(const label i)
{
    dispatch_.pelletContainer(i, bodies_[i], contacts_);
}


void Foam::rbd::world::findContacts(const bool withSleepers)
{
    contacts_.clear();

    pointField x(bodies_.size());
    forAll(bodies_, i)
    {
        x[i] = bodies_[i].x();
    }
    neighbours_.update(x, 2*rb_ + band_);

    // The narrow phase of the pairs: nonsphere pairs on the threads in
    // chunks of pairsPerChunk, each chunk taken by the next thread free (a
    // pair costs from one box test to hundreds of leaf pairs, so equal
    // runs of pairs per thread can leave threads idle) and
    // written to its own list; the lists are joined in the chunks' order,
    // so the contact list (and the packing) is the same for any number of
    // threads. Sphere pairs cost less than a thread's start.
    const UList<labelPair> pairs
    (
        withSleepers ? UList<labelPair>(neighbours_.pairs()) : activePairs()
    );
    const label nPairs = pairs.size();
    const label nChunks = (nPairs + pairsPerChunk - 1)/pairsPerChunk;
    const label nThreads =
        !dispatch_.spheres() ? min(controls_.threads, nChunks) : 1;
    if (nThreads > 1)
    {
        if (label(chunkContacts_.size()) < nChunks)
        {
            chunkContacts_.resize(nChunks);
        }
        #pragma omp parallel for num_threads(nThreads) schedule(dynamic, 1)
        for (label c = 0; c < nChunks; ++c)
        {
            const label t = omp_get_thread_num();
            DynamicList<contact>& found = chunkContacts_[c];
            found.clear();
            const label end = min(nPairs, (c + 1)*pairsPerChunk);
            for (label p = c*pairsPerChunk; p < end; ++p)
            {
                pelletPair(pairs[p], found, t);
            }
        }
        for (label c = 0; c < nChunks; ++c)
        {
            contacts_.append(chunkContacts_[c]);
        }
    }
    else
    {
        for (const labelPair& pr : pairs)
        {
            pelletPair(pr, contacts_, 0);
        }
    }

    if (withSleepers)
    {
        forAll(bodies_, i)
        {
            pelletContainer(i);
        }
    }
    else
    {
        for (const label i : awake())
        {
            pelletContainer(i);
        }
    }

    for (const contact& ct : contacts_)
    {
        // 0 - gap: +0 for a gap of exactly 0 (-gap prints as -0)
        stats_.maxOverlap = max(stats_.maxOverlap, 0 - ct.gap);
    }
}


Foam::scalar Foam::rbd::world::sweptAdvance
(
    const label i,
    const rigidBody& b
)
{
    scalar d = GREAT;
    // (no contact: gap 0 not seen, i.e. stepControl::unseenClosing)
    auto seenOrNot = [&]()
    {
        if (sweepContacts_.empty())
        {
            return sweep_.advanceFor(0, false);
        }
        scalar gap = GREAT;
        for (const contact& c : sweepContacts_)
        {
            gap = min(gap, c.gap);
        }
        return sweep_.advanceFor(gap, true);
    };
    for (const label k : sweepNear_)
    {
        const scalar bounding = mag(b.x() - bodies_[k].x()) - 2*rb_;
        if (bounding >= band_)
        {
            d = min(d, sweep_.advanceFor(bounding, false));
            continue;
        }
        sweepContacts_.clear();
        dispatch_.pelletPair(i, b, k, bodies_[k], sweepContacts_, 0);
        d = min(d, seenOrNot());
    }
    if (sweepNearContainer_)
    {
        const scalar bounding = min
        (
            b.x().z() - rb_,
            tube_.radius() - tube::axialDistance(b.x()) - rb_
        );
        if (bounding >= band_)
        {
            d = min(d, sweep_.advanceFor(bounding, false));
        }
        else
        {
            sweepContacts_.clear();
            dispatch_.pelletContainer(i, b, sweepContacts_);
            d = min(d, seenOrNot());
        }
    }
    return d;
}


void Foam::rbd::world::projectOverlaps()
{
    stats_.projections +=
        projection_.correct(bodies_, fixed_, tube_, contacts_);
}


void Foam::rbd::world::updateSleep(const scalar h)
{
    boolList sleeps;
    if (!sleep_.fallAsleep(h, bodies_, fixed_, awake(), contacts_, sleeps))
    {
        return;
    }
    for (const label i : awake())
    {
        if (sleeps[i])
        {
            rigidBody& b = bodies_[i];
            fixed_[i] = true;
            b.setState(b.x(), b.q(), Zero, Zero);
            F_[i] = Zero;
            tau_[i] = Zero;
        }
    }
    sleepSetChanged();
}


bool Foam::rbd::world::wake(const label i)
{
    const bool woke =
        sleep_.wake(i, bodies_, fixed_, neighbours_.adjacency());
    if (woke)
    {
        sleepSetChanged();
    }
    return woke;
}


Foam::scalar Foam::rbd::world::step(const scalar hMax)
{
    const scalar g = controls_.gravity;

    // 1-2. Broad and narrow phase
    findContacts();

    // 3. Residual interpenetration
    projectOverlaps();


    // Sleeping bodies hit hard (faster than wakeVelocity) wake up first,
    // and the contact list is built again with them awake (their contacts
    // with the container and other sleepers were missing). Only these hits
    // wake: in the collision stage a sleeper takes any impulse as the wall
    // does, so an impact on the bed is not passed on through the settled
    // pellets below it. Hard bodies pass an impulse down a touching chain
    // within one sweep: with the threshold eps_p, every pellet arriving
    // woke the bed down to the floor; with wakes in the sweeps at
    // wakeVelocity, a layer of pellets landing at once still did (the
    // layers feed, docs/loadingSpeed.md), and a sleeper woken there was
    // stepped without its contacts unless the stage was run again
    bool woke = false;
    for (const contact& c : contacts_)
    {
        if (c.k >= 0 && fixed_[c.k] && c.gap <= touch_)
        {
            const scalar vn = bodies_[c.i].pointVelocity(c.p) & c.n;
            if (collisions_.wakes(c, vn, fixed_))
            {
                woke = wake(c.k) || woke;
            }
        }
    }
    if (woke)
    {
        findContacts();
    }

    // 4. Collisions
    {
        const scalar energyBefore = contacts_.size() ? kineticEnergy() : 0;
        const collisionResolver::result cr =
            collisions_.resolve(bodies_, contacts_, touch_, fixed_);
        if (cr.impulses && energyBefore > 0)
        {
            stats_.maxCollisionEnergyGain = max
            (
                stats_.maxCollisionEnergyGain,
                (kineticEnergy() - energyBefore)/energyBefore
            );
        }
        stats_.collisions += cr.collisions;
        stats_.impulses += cr.impulses;
        stats_.collisionSweeps += cr.sweeps;
    }

    // 5. Step length. A step that collapses would stall the run without a
    //    word (1e-18 s seen when the contact tolerance exceeded the band;
    //    the shortest in the validation beds is ~4e-9 s): stop instead.
    //    With sweepSpeed, fast pellets clear of everything are swept
    //    (pelletSweep): held still for the bounds, they do not bound the
    //    step. Of the candidates only those are swept whose own bounds (their
    //    pairs', contacts', container's) lie below the step their sweep
    //    allows: the others do not bound it, and a sweep costs narrow
    //    phases. The step of the sweep holds for them unswept too (their
    //    own bounds are longer, the rest are the same or one-sided)
    sweep_.select
    (
        bodies_, fixed_, awake(), contacts_, neighbours_.adjacency(), swept_
    );
    scalar h = stepControl_.choose
    (
        hMax, bodies_, fixed_, awake(), activePairs(), contacts_,
        neighbours_.slack(), swept_.size() ? &bodyBound_ : nullptr
    );
    if (swept_.size())
    {
        held_ = fixed_;
        for (const label i : swept_)
        {
            held_[i] = true;
        }
        const scalar hSwept = stepControl_.choose
        (
            hMax, bodies_, held_, awake(), activePairs(), contacts_,
            neighbours_.slack()
        );
        label n = 0;
        for (const label i : swept_)
        {
            if (bodyBound_[i] < hSwept)
            {
                swept_[n++] = i;
            }
            else
            {
                held_[i] = false;
            }
        }
        swept_.resize(n);
        if (n)
        {
            h = hSwept;
        }
    }
    const scalar minStep = 1e-12;
    const label maxTinySteps = 1000;
    tinySteps_ = h < minStep && h < hMax ? tinySteps_ + 1 : 0;
    if (tinySteps_ > maxTinySteps)
    {
        FatalErrorInFunction
            << "The time step stayed below " << minStep << " s for "
            << maxTinySteps << " steps at t = " << time_ << " s (last "
            << h << " s; " << bodies_.size() << " pellets, "
            << contacts_.size() << " contacts): the run cannot go on."
            << nl << "    Check simulation/proximity and contactTolerance"
            << " (the band must hold the tolerated interpenetration)"
            << exit(FatalError);
    }

    // 6. Contact forces. Every contact within the band takes part: the
    //    constraint of a separating or distant contact is inactive unless
    //    the forces of its neighbours would drive it into interpenetration
    //    within the step, which is exactly when it must act.
    //    A sleeper's entries are zero (set when it fell asleep)
    if (F_.size() != bodies_.size())
    {
        F_.setSize(bodies_.size());
        tau_.setSize(bodies_.size());
        F_ = Zero;
        tau_ = Zero;
    }
    for (const label i : awake())
    {
        F_[i] = vector(0, 0, -g*bodies_[i].mass());
        tau_[i] = Zero;
    }

    //    A swept pellet is clear of everything and takes no force: it is held
    //    like a sleeper, so that the others' contacts with it keep them
    //    off where it is (its sweep starts there). The solve moves the
    //    first body of a contact (the awake one first where one sleeps):
    //    a swept pellet's contact with a moving pellet is turned round,
    //    its contacts with the container and sleepers move nothing
    const boolList& held = swept_.size() ? held_ : fixed_;
    const UList<contact>* resting = &contacts_;
    if (swept_.size())
    {
        restingContacts_.clear();
        for (const contact& c : contacts_)
        {
            if (!held_[c.i])
            {
                restingContacts_.append(c);
            }
            else if (c.k >= 0 && !held_[c.k])
            {
                restingContacts_.append(reversed(c));
            }
        }
        resting = &restingContacts_;
    }
    if (resting->size())
    {
        const restingContactSolver::result rr = resting_.solve
        (
            bodies_, *resting, held, h, F_, tau_
        );
        rolling_.apply
        (
            bodies_, *resting, resting_.normalForces(), held, h, tau_
        );
        ++stats_.restingSolves;
        stats_.lcpIterations += rr.iterations;
        stats_.largestIsland = max(stats_.largestIsland, rr.largestIsland);
        if (!rr.converged)
        {
            ++stats_.lcpFailures;
        }
    }

    // 7. Integration, then the swept pellets stopped at their first touch
    sweptStart_.clear();
    for (const label i : swept_)
    {
        sweptStart_.append(bodies_[i]);
    }
    for (const label i : awake())
    {
        midpointIntegrator::step(bodies_[i], F_[i], tau_[i], h);
    }
    forAll(swept_, j)
    {
        // What its bounding sphere comes within the band of along the
        // path; the others are at least the band away all along
        const label i = swept_[j];
        const point& x0 = sweptStart_[j].x();
        const point& x1 = bodies_[i].x();
        sweepNear_.clear();
        for (const label k : neighbours_.adjacency()[i])
        {
            if (!sweep_.clearOf(x0, x1, bodies_[k].x(), band_))
            {
                sweepNear_.append(k);
            }
        }
        sweepNearContainer_ = !sweep_.clearOfContainer(x0, x1, band_);
        const scalar s =
            sweepNear_.empty() && !sweepNearContainer_
          ? 1
          : sweep_.sweep
            (
                sweptStart_[j], bodies_[i],
                [&](const rigidBody& b) { return sweptAdvance(i, b); }
            );
        ++stats_.sweptSteps;
        if (s < 1)
        {
            ++stats_.sweepStops;
        }
    }

    updateSleep(h);

    time_ += h;
    ++stats_.steps;
    stats_.minStep = min(stats_.minStep, h);

    return h;
}


void Foam::rbd::world::advance(const scalar dt)
{
    const scalar tEnd = time_ + dt;
    while (tEnd - time_ > 1e-12*max(dt, scalar(1)))
    {
        step(tEnd - time_);
    }
    time_ = tEnd;
}


Foam::label Foam::rbd::world::nMoving(const scalar speed) const
{
    label n = 0;
    forAll(bodies_, i)
    {
        const rigidBody& b = bodies_[i];
        if (!fixed_[i] && mag(b.v()) + mag(b.omega())*rb_ > speed)
        {
            ++n;
        }
    }
    return n;
}


Foam::label Foam::rbd::world::nSleeping() const
{
    label n = 0;
    for (const bool f : fixed_)
    {
        n += f;
    }
    return n;
}


Foam::scalar Foam::rbd::world::kineticEnergy() const
{
    // Sleepers have none (their momenta are zero)
    scalar E = 0;
    for (const label i : awake())
    {
        E += bodies_[i].kineticEnergy();
    }
    return E;
}


Foam::scalar Foam::rbd::world::potentialEnergy() const
{
    scalar E = 0;
    for (const rigidBody& b : bodies_)
    {
        E += b.mass()*controls_.gravity*b.x().z();
    }
    return E;
}


Foam::scalar Foam::rbd::world::currentMaxOverlap()
{
    scalar current = 0;
    for (const contact& c : allContacts())
    {
        current = max(current, 0 - c.gap);
    }
    stats_.maxOverlap = max(stats_.maxOverlap, current);
    return current;
}


const Foam::UList<Foam::rbd::contact>& Foam::rbd::world::allContacts()
{
    const statistics saved = stats_;
    findContacts(true);
    stats_ = saved;
    return contacts_;
}


void Foam::rbd::world::writeState(stateWriter& out) const
{
    out.put(bodies_.size());
    forAll(bodies_, i)
    {
        bodies_[i].writeState(out);
    }
    out.putList(fixed_);
    sleep_.writeState(out);
    neighbours_.writeState(out);
    resting_.writeState(out);

    out.put(time_).put(tinySteps_);
    const statistics& s = stats_;
    out.put(s.steps).put(s.collisions).put(s.impulses)
       .put(s.collisionSweeps).put(s.restingSolves).put(s.lcpIterations)
       .put(s.largestIsland).put(s.lcpFailures).put(s.projections)
       .put(s.maxOverlap).put(s.minStep).put(s.maxCollisionEnergyGain)
       .put(s.sweptSteps).put(s.sweepStops);
}


void Foam::rbd::world::readState(stateReader& in)
{
    if (bodies_.size())
    {
        FatalErrorInFunction
            << "A checkpoint is read into a world with no pellets"
            << abort(FatalError);
    }

    label n = 0;
    in.get(n);
    in.checkSize(n);
    for (label i = 0; i < n; ++i)
    {
        // The shape's constants, then the state as it was
        addBody(Zero, quaternion(1));
        bodies_[i].readState(in);
    }
    in.getList(fixed_);
    const label nSleep = sleep_.readState(in);
    sleepSetChanged();
    if (fixed_.size() != n || nSleep != n)
    {
        FatalErrorInFunction
            << "The checkpoint " << in.name().c_str() << " holds " << n
            << " pellets but sleep states of " << fixed_.size()
            << ": it is damaged." << nl
            << "    Delete it and run without -resume." << exit(FatalError);
    }
    // (its pairs are checked against its snapshots as it reads them)
    neighbours_.readState(in);
    if (neighbours_.adjacency().size() != n)
    {
        FatalErrorInFunction
            << "The checkpoint " << in.name().c_str() << " holds " << n
            << " pellets but neighbour lists of "
            << neighbours_.adjacency().size() << ": it is damaged." << nl
            << "    Delete it and run without -resume." << exit(FatalError);
    }
    resting_.readState(in);

    in.get(time_).get(tinySteps_);
    statistics& s = stats_;
    in.get(s.steps).get(s.collisions).get(s.impulses)
      .get(s.collisionSweeps).get(s.restingSolves).get(s.lcpIterations)
      .get(s.largestIsland).get(s.lcpFailures).get(s.projections)
      .get(s.maxOverlap).get(s.minStep).get(s.maxCollisionEnergyGain)
      .get(s.sweptSteps).get(s.sweepStops);
}


// ************************************************************************* //
