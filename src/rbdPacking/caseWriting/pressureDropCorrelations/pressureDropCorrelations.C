/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pressureDropCorrelations.H"
#include "error.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::wordList Foam::rbd::pressureDropCorrelations::shapes
({
    "spheres",
    "cylinders"
});


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::pressureDropCorrelations::ergun
(
    const scalar eps,
    const scalar dp,
    const scalar U,
    const scalar mu,
    const scalar rho
)
{
    const scalar eps3 = eps*eps*eps;
    return
        150*mu*sqr(1 - eps)*U/(eps3*sqr(dp))
      + 1.75*rho*(1 - eps)*sqr(U)/(eps3*dp);
}


Foam::scalar Foam::rbd::pressureDropCorrelations::eisfeldSchnitzlein
(
    const scalar eps,
    const scalar dp,
    const scalar dt,
    const scalar U,
    const scalar mu,
    const scalar rho,
    const word& shape
)
{
    scalar K1 = 154, k1 = 1.15, k2 = 0.87;
    if (shape == "cylinders")
    {
        K1 = 190;
        k1 = 2.00;
        k2 = 0.77;
    }
    else if (shape != "spheres")
    {
        FatalErrorInFunction
            << "No Eisfeld-Schnitzlein constants for shape '" << shape
            << "'; have " << shapes << exit(FatalError);
    }

    const scalar eps3 = eps*eps*eps;
    const scalar A = 1 + 2/(3*(dt/dp)*(1 - eps));
    const scalar B = sqr(k1*sqr(dp/dt) + k2);
    return
        K1*sqr(A)*mu*sqr(1 - eps)*U/(eps3*sqr(dp))
      + A/B*rho*(1 - eps)*sqr(U)/(eps3*dp);
}


// ************************************************************************* //
