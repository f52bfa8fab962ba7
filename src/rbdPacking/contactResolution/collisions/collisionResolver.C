/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "collisionResolver.H"
#include "labelPair.H"
#include "DynamicList.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::collisionResolver::collisionResolver
(
    const scalar epsP,
    const scalar epsF,
    const label restitutionSweeps,
    const label maxSweeps,
    const scalar approachTolerance,
    const scalar wakeVelocity
)
:
    epsP_(epsP),
    epsF_(epsF),
    approachTolerance_(approachTolerance),
    wakeVelocity_(wakeVelocity),
    restitutionSweeps_(restitutionSweeps),
    maxSweeps_(maxSweeps),
    version_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::rbd::collisionResolver::relativeVelocity
(
    const contact& c,
    const UList<rigidBody>& bodies,
    const boolList& fixed
)
{
    vector vRel(bodies[c.i].pointVelocity(c.p));
    if (c.k >= 0 && !fixed[c.k])
    {
        vRel -= bodies[c.k].pointVelocity(c.p);
    }
    return vRel;
}


Foam::scalar Foam::rbd::collisionResolver::effectiveInvMass
(
    const contact& c,
    const vector& d,
    const UList<rigidBody>& bodies,
    const boolList& fixed
)
{
    const rigidBody& bi = bodies[c.i];
    const vector ri(c.p - bi.x());
    scalar K = bi.invMass() + (d & (bi.applyInvInertia(ri ^ d) ^ ri));

    if (c.k >= 0 && !fixed[c.k])
    {
        const rigidBody& bk = bodies[c.k];
        const vector rk(c.p - bk.x());
        K += bk.invMass() + (d & (bk.applyInvInertia(rk ^ d) ^ rk));
    }
    return K;
}


void Foam::rbd::collisionResolver::applyImpulse
(
    const contact& c,
    const vector& J,
    UList<rigidBody>& bodies,
    const boolList& fixed
)
{
    bodies[c.i].applyImpulse(J, c.p);
    if (c.k >= 0 && !fixed[c.k])
    {
        bodies[c.k].applyImpulse(-J, c.p);
    }
}


Foam::rbd::collisionResolver::result
Foam::rbd::collisionResolver::resolve
(
    UList<rigidBody>& bodies,
    const UList<contact>& contacts,
    const scalar touchGap,
    const boolList& fixed
) const
{
    result res;

    // The touching contacts of moving bodies
    DynamicList<label> touching(contacts.size());
    forAll(contacts, ci)
    {
        if (contacts[ci].gap <= touchGap && !fixed[contacts[ci].i])
        {
            touching.append(ci);
        }
    }

    // An approach slower than this is left to the resting-contact solve,
    // which stops it within the step without interpenetration (and
    // without dissipating it: the contact leaves as fast as it came)
    const scalar vSlow = approachTolerance_*epsP_;

    // A contact found satisfied is skipped until an impulse changes one of
    // its bodies: version counts the impulses on each body, seen holds the
    // versions of a contact's bodies when it was last found satisfied. The
    // sweeps then cost what the impulses' spread costs, not the number of
    // touching contacts times the sweeps, with the same result.
    if (version_.size() < bodies.size())
    {
        version_.setSize(bodies.size(), 0);
    }
    labelList& version = version_;
    List<labelPair> seen(touching.size(), labelPair(-1, -1));

    for (label sweep = 0; sweep < maxSweeps_; ++sweep)
    {
        const bool withRestitution = sweep < restitutionSweeps_;
        bool applied = false;
        res.residual = 0;

        forAll(touching, ti)
        {
            const contact& c = contacts[touching[ti]];
            const labelPair versions
            (
                version[c.i], c.k >= 0 ? version[c.k] : 0
            );
            if (seen[ti] == versions)
            {
                continue;
            }

            const vector vRel(relativeVelocity(c, bodies, fixed));
            const scalar vn = vRel & c.n;

            if (vn >= -vSlow)
            {
                seen[ti] = versions;
                continue;
            }

            // Section 4: colliding or resting-but-approaching
            const bool colliding = vn < -epsP_;
            const scalar e = (colliding && withRestitution) ? c.e : 0;

            // A sleeping body takes the impulse as the wall does, however
            // fast: what a hit passes on through the pellets on the bed
            // is reflected at its surface, not passed into the settled
            // bed below (the hits that wake a sleeper are found before
            // the sweeps, world::step)

            res.residual = max(res.residual, -vn);

            // Normal impulse (eqs 21-23)
            const scalar jn =
                -(1 + e)*vn/effectiveInvMass(c, c.n, bodies, fixed);
            applyImpulse(c, jn*c.n, bodies, fixed);

            // Friction impulse (eq 24), clamped so it cannot reverse slip
            if (c.mu > 0)
            {
                const vector vRel1(relativeVelocity(c, bodies, fixed));
                const vector vt(vRel1 - (vRel1 & c.n)*c.n);
                const scalar slip = mag(vt);

                if (slip > epsF_)
                {
                    const vector t(-vt/slip);
                    const scalar jStick =
                        slip/effectiveInvMass(c, t, bodies, fixed);
                    applyImpulse(c, min(c.mu*jn, jStick)*t, bodies, fixed);
                }
            }

            ++version[c.i];
            if (c.k >= 0)
            {
                ++version[c.k];
            }

            applied = true;
            ++res.impulses;
            if (colliding)
            {
                ++res.collisions;
            }
        }

        res.sweeps = sweep + 1;
        if (!applied)
        {
            res.residual = 0;
            break;
        }
    }

    // The counts as between resolves
    for (const label ci : touching)
    {
        version[contacts[ci].i] = 0;
        if (contacts[ci].k >= 0)
        {
            version[contacts[ci].k] = 0;
        }
    }

    return res;
}


// ************************************************************************* //
