/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "stepControl.H"
#include "collisionResolver.H"
#include <algorithm>
#include <vector>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::stepControl::stepControl
(
    const scalar gravity,
    const scalar restingVelocity,
    const scalar band,
    const scalar touch,
    const scalar boundingRadius,
    const bool centreGaps,
    const bool exactSolids,
    const scalar tubeRadius
)
:
    g_(gravity),
    restingVelocity_(restingVelocity),
    band_(band),
    touch_(touch),
    rb_(boundingRadius),
    centreGaps_(centreGaps),
    exactSolids_(exactSolids),
    tubeRadius_(tubeRadius)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::stepControl::timeToCover
(
    const Foam::scalar a,
    const Foam::scalar b,
    const Foam::scalar c
)
{
    if (a <= 0)
    {
        return b > 0 ? c/b : Foam::GREAT;
    }
    // Stable form of (-b + sqrt(b^2 + 2 a c))/a
    return 2*c/(b + Foam::sqrt(Foam::sqr(b) + 2*a*c));
}


Foam::scalar Foam::rbd::stepControl::timeToLeaveCircle
(
    const Foam::vector& p,
    const Foam::vector& v,
    const Foam::scalar rho
)
{
    const Foam::scalar a = Foam::magSqr(v);
    if (a <= 0)
    {
        return Foam::GREAT;
    }
    const Foam::scalar b = p & v;
    const Foam::scalar c = Foam::min(Foam::magSqr(p) - Foam::sqr(rho), 0);
    const Foam::scalar root = Foam::sqrt(Foam::sqr(b) - a*c);
    // The positive root of a t^2 + 2 b t + c = 0, without cancellation
    return b > 0 ? -c/(b + root) : (root - b)/a;
}


Foam::scalar Foam::rbd::stepControl::unseenClosing() const
{
    return
        exactSolids_
      ? max(unseenGap*band_ - 0.5*touch_, 0.2*band_)
      : 0.2*band_;
}


Foam::scalar Foam::rbd::stepControl::choose
(
    const scalar hMax,
    const UList<rigidBody>& bodies,
    const boolList& held,
    const UList<label>& awake,
    const UList<labelPair>& activePairs,
    const UList<contact>& contacts,
    const UList<scalar>& listSlack,
    scalarList* bodyBound
) const
{
    const scalar g = g_;
    const scalar epsP = restingVelocity_;

    // Swept pellets stand still for every bound below but their own
    // unlisted pairs' (the others must not reach where they are unseen)
    const boolList& fixed = held;

    // Spheres: the gaps depend on the centres only, so rotation does not
    // close them; otherwise the surface moves up to |omega| r_b faster
    const bool centreGaps = centreGaps_;
    auto freeSurfaceSpeed = [&](const label i)
    {
        const rigidBody& b = bodies[i];
        return mag(b.v()) + (centreGaps ? 0 : mag(b.omega())*rb_);
    };
    auto surfaceSpeed = [&](const label i)
    {
        return fixed[i] ? 0 : freeSurfaceSpeed(i);
    };
    // ... and its centre's speed (a swept pellet's counts for nothing
    // here, as its surface's): surfaceSpeed - centreSpeed is what its
    // turn adds
    auto centreSpeed = [&](const label i)
    {
        return fixed[i] ? 0 : mag(bodies[i].v());
    };

    // Time for a gap closing at rate u (acceleration up to a) to shrink to
    // half the touching gap: the next step finds the pair touching and the
    // collision stage resolves it (the paper's "back up to the last state
    // before contact")
    auto untilTouching = [&](const scalar gap, const scalar u, const scalar a)
    {
        return timeToCover(a, max(u, scalar(0)), max(gap - 0.5*touch_, 0.0));
    };

    scalar h = hMax;
    if (bodyBound)
    {
        bodyBound->resize(bodies.size());
        *bodyBound = hMax;
    }

    // A bound of bodies i and k (-1: none, or the container)
    auto bound = [&](const scalar hb, const label i, const label k)
    {
        h = min(h, hb);
        if (bodyBound)
        {
            for (const label b : {i, k})
            {
                if (b >= 0)
                {
                    (*bodyBound)[b] = min((*bodyBound)[b], hb);
                }
            }
        }
    };

    // 1. Pairs the broad phase has not listed are at least cutoff + c_i +
    //    c_k apart (c: each body's slack, skin/2 less its distance from
    //    its snapshot), i.e. their bounding spheres at least lambda + c_i
    //    + c_k: each body may cover half of lambda (less half the touching
    //    gap) and its own slack, under gravity. The same bound as lambda +
    //    skin - 2 max|x - X| against twice the fastest body for the body
    //    with the least slack, and a longer one where the fast bodies are
    //    the ones just listed again
    //    (a swept pellet too, at its own speed: it is swept against its
    //    listed neighbours only; the awake are held only where swept)
    for (const label i : awake)
    {
        bound
        (
            timeToCover
            (
                g, freeSurfaceSpeed(i),
                max(0.5*(band_ - 0.5*touch_) + listSlack[i], 0.0)
            ),
            i, -1
        );
    }

    // Eq 38 for a pair (k < 0: the container) whose bounding spheres are
    // within the band: delta_t <= 0.2 lambda/|v_ik,max|, |v_ik,max| the
    // largest relative surface speed |v_i - v_k| + (|omega_i| + |omega_k|)
    // r_b (spheres: of the centres). Needed for meshes: a pair may be
    // within the band of its bounding spheres before any feature is
    // within the band of the surfaces, and no feature may then cross the
    // band in one step.
    auto closeBy = [&](const label i, const label k, const scalar closing)
    {
        const bool kMoves = k >= 0 && !fixed[k];
        const vector vCentres
        (
            (fixed[i] ? Zero : bodies[i].v())
          - (kMoves ? bodies[k].v() : Zero)
        );
        scalar speed = mag(vCentres);
        if (!centreGaps)
        {
            speed +=
                (
                    (fixed[i] ? 0 : mag(bodies[i].omega()))
                  + (kMoves ? mag(bodies[k].omega()) : 0)
                )*rb_;
        }
        // ... closing also under an acceleration up to g per moving body
        // for meshes: a pair at rest within the band of its bounding
        // spheres but with no feature within the band (no contact yet) is
        // otherwise given the outer interval, and a pellet starting to
        // fall onto another closes g h^2/2 in it (3 mm at 1/40 s: a ring
        // released 1 mm over another went 0.7 mm into it). (Spheres have
        // their contact within the band, held by the resting solve.)
        const scalar a =
            centreGaps ? 0 : (k < 0 || !kMoves || fixed[i]) ? g : 2*g;
        return timeToCover(a, speed, closing);
    };
    auto eq38 = [&](const label i, const label k)
    {
        return closeBy(i, k, 0.2*band_);
    };

    // A pair of exact solids within the band of its bounding spheres but
    // with no contact has no feature within the band: it may close by
    // unseenClosing(), not only by eq 38's 0.2 lambda
    const scalar unseen = unseenClosing();
    std::vector<std::pair<label, label>> inContact;
    std::vector<bool> onFloor(exactSolids_ ? bodies.size() : 0, false);
    std::vector<bool> onWall(exactSolids_ ? bodies.size() : 0, false);
    if (exactSolids_)
    {
        for (const contact& c : contacts)
        {
            if (c.k >= 0)
            {
                inContact.emplace_back(min(c.i, c.k), max(c.i, c.k));
            }
            else
            {
                (c.k == tubeBottom ? onFloor : onWall)[c.i] = true;
            }
        }
        std::sort(inContact.begin(), inContact.end());
    }
    auto hasContact = [&](const label i, const label k)
    {
        return !exactSolids_ || std::binary_search
        (
            inContact.begin(), inContact.end(),
            std::pair<label, label>(min(i, k), max(i, k))
        );
    };
    auto withinBand = [&](const label i, const label k, const bool seen)
    {
        return closeBy(i, k, seen ? 0.2*band_ : unseen);
    };

    // 2. Listed pairs apart by more than the band: their bounding spheres
    //    may approach until touching
    for (const labelPair& pr : activePairs)
    {
        const label i = pr.first();
        const label k = pr.second();
        if (fixed[i] && fixed[k])
        {
            // A swept pellet and a sleeper
            continue;
        }
        const vector d(bodies[i].x() - bodies[k].x());
        const scalar dist = mag(d);
        const scalar gap = dist - 2*rb_;
        if (gap > band_)
        {
            const vector vRel
            (
                (fixed[i] ? Zero : bodies[i].v())
              - (fixed[k] ? Zero : bodies[k].v())
            );
            const scalar u =
              - (vRel & d)/dist + surfaceSpeed(i) - centreSpeed(i)
              + surfaceSpeed(k) - centreSpeed(k);
            const scalar a = (fixed[i] || fixed[k]) ? g : 2*g;
            bound(untilTouching(gap, u, a), i, k);
        }
        else if (!centreGaps)
        {
            const bool seen = hasContact(i, k);
            bound
            (
                fixed[i] ? withinBand(k, i, seen) : withinBand(i, k, seen),
                i, k
            );
        }
    }

    // ... and the container, the same way
    const scalar R = tubeRadius_;

    // The path along the wall that its curvature turns into half the
    // touching gap (a sphere on the wall, below)
    const scalar wallPath = std::sqrt(max(R - rb_, 0.0)*touch_);
    for (const label i : awake)
    {
        if (fixed[i])
        {
            continue;
        }
        const rigidBody& b = bodies[i];
        const scalar spin = surfaceSpeed(i) - mag(b.v());
        const scalar zGap = b.x().z() - rb_;
        if (zGap > band_)
        {
            bound(untilTouching(zGap, -b.v().z() + spin, g), i, -1);
        }
        else if (!centreGaps)
        {
            bound
            (
                withinBand(i, tubeBottom, !exactSolids_ || onFloor[i]), i, -1
            );
        }
        const vector rho(b.x().x(), b.x().y(), 0);
        const scalar rhoMag = mag(rho);
        const scalar wallGap = R - rhoMag - rb_;
        if (wallGap > band_ && (rhoMag > VSMALL || centreGaps))
        {
            // Radial speed (a sphere on the axis: the exact time below)
            if (rhoMag > VSMALL)
            {
                const scalar u = (b.v() & rho)/rhoMag + spin;
                bound(untilTouching(wallGap, u, g), i, -1);
            }

            // The wall is concave: a pellet moving along it closes the gap
            // faster than its radial speed says (the gap along a straight
            // path is concave in time, closing with v_t^2/rho on top of
            // the radial speed). The exact time for the centre's
            // horizontal path to reach the radius of touching: without
            // it, a sphere skimming the wall of a 31 mm tube at 1.1 m/s
            // went 4e-5 m into it in one 1 ms step.
            const vector vH(b.v().x(), b.v().y(), 0);
            bound
            (
                timeToLeaveCircle(rho, vH, R - rb_ - 0.5*touch_), i, -1
            );
        }
        else if (!centreGaps)
        {
            // Within the band (or on the axis): eq 38
            bound
            (
                withinBand(i, tubeWall, !exactSolids_ || onWall[i]), i, -1
            );
        }
    }

    // 3. Contacts within the band
    for (const contact& c : contacts)
    {
        if (fixed[c.i] && (c.k < 0 || fixed[c.k]))
        {
            // A swept pellet's contact with a sleeper or the container
            continue;
        }
        const vector vRel
        (
            collisionResolver::relativeVelocity(c, bodies, fixed)
        );

        // Eq 38 for the pair of every contact, but for a sphere's contact
        // with another sphere or the floor: the resting solve holds its
        // gap linearised along the normal of the step's start, d + h n .
        // (x_i - x_k)' >= 0 at the step's end, and the true gap, |r + D|
        // - 2a (r the centres' offset, D its change) or the height over
        // the flat floor, is at least that linear gap (|r + D| >= r^ .
        // (r + D)): the pair cannot close unseen whatever the step. An
        // approaching one is bounded below. Not for the wall: it is
        // concave, a sphere moving along it closes the gap by up to
        // h^2 |v_t|^2/(2 (R - a)) more than the linear gap says (likely
        // what sent the soak's fast drop 0.67 % of dp into something when
        // an earlier attempt dropped eq 38 for the wall too; not traced).
        // On the 500-sphere bed: 30 % fewer steps (docs/loadingSpeed.md)
        if (!centreGaps || c.k == tubeWall)
        {
            bound(eq38(c.i, c.k), c.i, c.k);
        }

        // A sphere on the wall: the resting solve holds the linear gap,
        // and a path s along the concave wall closes the true gap by up
        // to s^2/(2 (R - r)) more. At most half the touching gap: s <=
        // sqrt((R - r) touch), covered from the centre's horizontal speed
        // under an acceleration up to g (the wall is straight in z). Its
        // neighbours push a sphere along the wall at up to about g: in
        // 3-7 ms steps spheres went 0.13-0.25 mm sideways and up to 2.4
        // um into the wall; with this bound 1.4 um at most, in the same
        // CPU time (500 placed spheres; docs/stepLength.md)
        if (centreGaps && c.k == tubeWall && !fixed[c.i])
        {
            const vector& v = bodies[c.i].v();
            bound
            (
                timeToCover(g, mag(vector(v.x(), v.y(), 0)), wallPath),
                c.i, c.k
            );
        }

        // Approaching contacts stop at the touching gap
        if (c.gap > touch_)
        {
            const scalar vn = (vRel & c.n);
            if (vn < -epsP)
            {
                // Colliding soon: gravity counted
                bound(untilTouching(c.gap, -vn, g), c.i, c.k);
            }
            else if (vn < 0 && !(centreGaps && c.k != tubeWall))
            {
                // Resting approach: the resting-contact solve holds the
                // acceleration, the step bounds the closing velocity.
                // Not for a sphere's contact with another sphere or the
                // floor: the resting solve asks its linear gap d + h d' +
                // h^2 d''/2 >= 0 at the step's end (normalRows::normalB),
                // which the true gap is never below (as for eq 38 above),
                // so the approach, slower than eps_p, lands on the
                // touching gap within the step and leaves it at most as
                // fast as it came (500 spheres: 0.83 of the steps;
                // docs/stepLength.md)
                bound(untilTouching(c.gap, -vn, 0), c.i, c.k);
            }
        }
    }

    return h;
}


// ************************************************************************* //
