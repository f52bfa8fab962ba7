/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "overlapProjection.H"
#include "sphereContacts.H"
#include "meshContacts.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::rbd::overlapProjection::correct
(
    UList<rigidBody>& bodies,
    const boolList& fixed,
    const tube& container,
    UList<contact>& contacts
) const
{
    label corrections = 0;
    for (label sweep = 0; sweep < maxSweeps; ++sweep)
    {
        bool moved = false;
        for (contact& c : contacts)
        {
            c.gap =
                c.centreBased
              ? sphereContacts::gap(c, bodies, rb_, container)
              : meshContacts::gap(c, bodies, container);
            if (c.gap >= -slop_)
            {
                continue;
            }
            const scalar wi = fixed[c.i] ? 0 : bodies[c.i].invMass();
            const scalar wk =
                (c.k >= 0 && !fixed[c.k]) ? bodies[c.k].invMass() : 0;
            if (wi + wk <= 0)
            {
                continue;
            }
            const scalar depth = -c.gap - 0.5*slop_;
            const vector dx((depth/(wi + wk))*c.n);
            bodies[c.i].displace(wi*dx);
            if (wk > 0)
            {
                bodies[c.k].displace(-wk*dx);
            }
            c.gap = -0.5*slop_;
            moved = true;
            ++corrections;
        }
        if (!moved)
        {
            break;
        }
    }
    return corrections;
}


// ************************************************************************* //
