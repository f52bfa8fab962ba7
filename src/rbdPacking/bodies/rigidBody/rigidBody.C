/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "rigidBody.H"
#include "stateIO.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::rigidBody::rigidBody
(
    const scalar mass,
    const vector& principalInertia,
    const point& x,
    const quaternion& q,
    const bool rotates
)
:
    invMass_(1/mass),
    invInertiaBody_
    (
        1/principalInertia.x(),
        1/principalInertia.y(),
        1/principalInertia.z()
    ),
    isotropic_
    (
        mag(principalInertia.x() - principalInertia.y())
      + mag(principalInertia.x() - principalInertia.z())
     <= 1e-12*mag(principalInertia)
    ),
    rotates_(rotates),
    x_(x),
    q_(q),
    P_(Zero),
    L_(Zero),
    v_(Zero),
    omega_(Zero),
    R_(q.R()),
    invInertia_(Zero)
{
    setState(x, q, Zero, Zero);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::rbd::rigidBody::omegaOf
(
    const quaternion& q,
    const vector& L
) const
{
    if (!rotates_)
    {
        return Zero;
    }
    if (isotropic_)
    {
        return invInertiaBody_.x()*L;
    }
    // omega = R I_b^-1 R^T L (eq 3)
    const tensor R(q.R());
    const vector Lb(R.T() & L);
    return R & vector(cmptMultiply(invInertiaBody_, Lb));
}


void Foam::rbd::rigidBody::setState
(
    const point& x,
    const quaternion& q,
    const vector& P,
    const vector& L
)
{
    x_ = x;
    q_ = q;
    P_ = P;
    L_ = rotates_ ? L : Zero;
    v_ = invMass_*P_;

    if (!isotropic_)
    {
        R_ = q_.R();
        invInertia_ =
            R_
          & tensor
            (
                invInertiaBody_.x(), 0, 0,
                0, invInertiaBody_.y(), 0,
                0, 0, invInertiaBody_.z()
            )
          & R_.T();
    }
    else
    {
        R_ = q_.R();
        invInertia_ = invInertiaBody_.x()*tensor::I;
    }
    omega_ = applyInvInertia(L_);
}


void Foam::rbd::rigidBody::writeState(stateWriter& out) const
{
    out.put(x_).put(q_).put(P_).put(L_)
       .put(v_).put(omega_).put(R_).put(invInertia_);
}


void Foam::rbd::rigidBody::readState(stateReader& in)
{
    in.get(x_).get(q_).get(P_).get(L_)
      .get(v_).get(omega_).get(R_).get(invInertia_);
}


// ************************************************************************* //
