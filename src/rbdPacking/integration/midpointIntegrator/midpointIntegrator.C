/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "midpointIntegrator.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::midpointIntegrator::step
(
    rigidBody& b,
    const vector& F,
    const vector& tau,
    const scalar h
)
{
    const quaternion& q0 = b.q();

    // Midpoint state (eq 5): P and L at t + h/2; v follows from P
    const vector Ph = b.P() + 0.5*h*F;
    const vector vh = b.invMass()*Ph;

    quaternion q1(q0);
    vector L1(b.L());

    if (b.rotates())
    {
        const vector Lh = b.L() + 0.5*h*tau;

        quaternion qh(q0);
        qh += 0.5*h*qDot(b.omega(), q0);
        qh.normalize();

        const vector omegah = b.omegaOf(qh, Lh);

        // Full step from X^m with the midpoint derivative (eq 4)
        q1 += h*qDot(omegah, qh);
        q1.normalize();
        L1 += h*tau;
    }

    b.setState(b.x() + h*vh, q1, b.P() + h*F, L1);
}


// ************************************************************************* //
