/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "rollingResistance.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::rollingResistance::rollingResistance
(
    const scalar coefficient,
    const scalar radius
)
:
    coefficient_(coefficient),
    radius_(radius),
    loaded_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::rollingResistance::apply
(
    const UList<rigidBody>& bodies,
    const UList<contact>& contacts,
    const UList<scalar>& N,
    const UList<bool>& fixed,
    const scalar h,
    UList<vector>& tau
) const
{
    if (!active() || contacts.empty())
    {
        return;
    }

    auto movable = [&](const label b)
    {
        return b >= 0 && !fixed[b];
    };

    loaded_.assign(bodies.size(), 0);
    forAll(contacts, ci)
    {
        if (N[ci] > 0)
        {
            for (const label b : {contacts[ci].i, contacts[ci].k})
            {
                if (movable(b))
                {
                    ++loaded_[b];
                }
            }
        }
    }

    forAll(contacts, ci)
    {
        if (!(N[ci] > 0))
        {
            continue;
        }
        const contact& c = contacts[ci];
        const bool iMoves = movable(c.i);
        const bool kMoves = movable(c.k);
        if (!iMoves && !kMoves)
        {
            continue;
        }
        vector omegaRel(iMoves ? bodies[c.i].omega() : Zero);
        if (kMoves)
        {
            omegaRel -= bodies[c.k].omega();
        }
        const vector omegaR(omegaRel - (omegaRel & c.n)*c.n);
        const scalar w = mag(omegaR);
        if (w < VSMALL)
        {
            continue;
        }
        const vector u(omegaR/w);
        scalar invI = 0;
        label m = 1;
        if (iMoves)
        {
            invI += (u & bodies[c.i].applyInvInertia(u));
            m = max(m, loaded_[c.i]);
        }
        if (kMoves)
        {
            invI += (u & bodies[c.k].applyInvInertia(u));
            m = max(m, loaded_[c.k]);
        }
        if (!(invI > 0))
        {
            continue;
        }
        const scalar T =
            min(coefficient_*radius_*N[ci], w/(h*invI*m));
        if (iMoves)
        {
            tau[c.i] -= T*u;
        }
        if (kMoves)
        {
            tau[c.k] += T*u;
        }
    }
}


// ************************************************************************* //
