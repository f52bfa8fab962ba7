/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "meshedPellet.H"
#include "massProperties.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::meshedPellet::meshedPellet
(
    const dictionary& dict,
    const label defaultFaces
)
:
    pelletShape(dict, defaultFaces),
    surface_(),
    volume_(0),
    area_(0),
    inertia_(Zero),
    toBodyRotation_(tensor::I),
    toBodyTranslation_(Zero)
{}


// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

void Foam::rbd::meshedPellet::setSurface(const triMesh& mesh)
{
    const massProperties mp(mesh, 1);
    surface_ = mp.toPrincipalFrame(mesh);
    volume_ = mp.volume();
    area_ = surface_.area();
    inertia_ = mp.principalMoments();
    // As massProperties::toPrincipalFrame
    toBodyRotation_ = mp.principalRotation().T();
    toBodyTranslation_ = -(toBodyRotation_ & mp.centreOfMass());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::meshedPellet::write(Ostream& os) const
{
    pelletShape::write(os);
    os.writeKeyword("mesh") << surface_.nFaces() << " faces, volume "
        << volume_ << " m^3, bounding radius " << boundingRadius() << " m"
        << token::END_STATEMENT << nl;
}


// ************************************************************************* //
