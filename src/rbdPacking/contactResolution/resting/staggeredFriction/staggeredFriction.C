/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "staggeredFriction.H"
#include "collisionResolver.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * //

void Foam::rbd::staggeredFriction
(
    const restingProblem& p,
    const std::vector<bool>& staggered,
    const std::vector<label>& moved,
    const List<scalar>& phiAll,
    const UList<vector>& Fext,
    const UList<vector>& tauExt,
    UList<vector>& Ftot,
    UList<vector>& tauTot,
    UList<vector>& Ffric,
    UList<vector>& tauFric,
    List<vector>& friction
)
{
    const UList<rigidBody>& bodies = p.bodies;
    const UList<contact>& contacts = p.contacts;
    const boolList& fixed = p.fixed;
    const scalar h = p.h;

    // Friction from the predicted slip at the end of the step, clamped
    // to mu phi (eq 9); two Gauss-Seidel sweeps for coupled contacts
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
}


// ************************************************************************* //
