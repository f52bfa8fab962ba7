/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "contactDispatch.H"
#include "sphereContacts.H"
#include "cylinderContacts.H"
#include "cylinder.H"
#include "ring.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::contactDispatch::contactDispatch
(
    const pelletShape& shape,
    const tube& container,
    const scalar restitution,
    const scalar friction,
    const scalar band,
    const word& contactModel,
    const label threads
)
:
    shape_(shape),
    tube_(container),
    restitution_(restitution),
    friction_(friction),
    rb_(shape.boundingRadius()),
    band_(band),
    meshes_(),
    prism_(),
    prisms_(),
    hullRadius_(0),
    hullHalfHeight_(0),
    hullRimAngles_()
{
    const word model(pairModel(shape_, contactModel));
    const label nThreads = max(threads, label(1));
    if (model == "prism")
    {
        prism_ = shape_.prism();
        prisms_.setSize(nThreads);
        forAll(prisms_, t)
        {
            prisms_.set(t, new prismContacts(prism_(), band_));
        }
        return;
    }
    if (model == "mesh")
    {
        meshes_.setSize(nThreads);
        forAll(meshes_, t)
        {
            meshes_.set(t, new meshContacts(shape_.mesh(), band_));
        }
    }

    // auto: the container by the hull where the shape has one (its rims
    // as the mesh's polygons); contactModel mesh: by the mesh
    if (model == "mesh" && contactModel != "mesh")
    {
        if (isA<cylinder>(shape_))
        {
            const cylinder& s = refCast<const cylinder>(shape_);
            hullRadius_ = 0.5*s.diameter();
            hullHalfHeight_ = 0.5*s.height();
        }
        else if (isA<ring>(shape_))
        {
            const ring& s = refCast<const ring>(shape_);
            hullRadius_ = 0.5*s.diameter();
            hullHalfHeight_ = 0.5*s.height();
        }
        if (hullRadius_ > 0)
        {
            hullRimAngles_ = cylinderContacts::rimAngles
            (
                shape_.mesh().points(), hullRadius_
            );
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::word Foam::rbd::contactDispatch::pairModel
(
    const pelletShape& shape,
    const word& contactModel
)
{
    if (contactModel == "mesh")
    {
        return "mesh";
    }
    if (shape.isSphere())
    {
        return "sphere";
    }
    const bool hasPrism = shape.prism().valid();
    if (contactModel == "exact")
    {
        if (!hasPrism)
        {
            FatalErrorInFunction
                << "contactModel exact: pellets of shape " << shape.type()
                << " have no exact contacts (they have them: sphere,"
                << " cylinder, ring, trilobe, quadrilobe, cylinderWithHoles);"
                << " use contactModel auto or mesh" << exit(FatalError);
        }
        return "prism";
    }
    return "mesh";
}


void Foam::rbd::contactDispatch::pelletPair
(
    const label i,
    const rigidBody& bi,
    const label k,
    const rigidBody& bk,
    DynamicList<contact>& contacts,
    const label thread
) const
{
    const label start = contacts.size();
    if (!prisms_.empty())
    {
        prisms_[thread].prismPrism(i, bi, k, bk, contacts);
    }
    else if (meshes())
    {
        meshes_[thread].meshMesh(i, bi, k, bk, contacts);
    }
    else
    {
        contact c;
        if (sphereContacts::sphereSphere(i, bi, rb_, k, bk, rb_, band_, c))
        {
            contacts.append(c);
        }
    }

    // The pair's material (the container's is set by the generators)
    for (label ci = start; ci < contacts.size(); ++ci)
    {
        contacts[ci].e = restitution_;
        contacts[ci].mu = friction_;
    }
}


void Foam::rbd::contactDispatch::pelletContainer
(
    const label i,
    const rigidBody& bi,
    DynamicList<contact>& contacts
) const
{
    if (!prisms_.empty())
    {
        prisms_[0].prismTube(i, bi, tube_, contacts);
    }
    else if (!meshes())
    {
        sphereContacts::sphereTube(i, bi, rb_, tube_, band_, contacts);
    }
    else if (hullRadius_ > 0)
    {
        cylinderContacts::cylinderTube
        (
            i, bi, hullRadius_, hullHalfHeight_, tube_, band_, contacts,
            hullRimAngles_
        );
    }
    else
    {
        meshes_[0].meshTube(i, bi, tube_, contacts);
    }
}


void Foam::rbd::contactDispatch::describe(Ostream& os) const
{
    if (!prisms_.empty())
    {
        os  << "exact " << shape_.type() << " contacts (" << shape_.type()
            << " features, " << prisms_[0].nSamples() << " samples of its"
            << " rims and walls, against the other's exact signed distance,"
            << " both ways) between pellets and with the container";
    }
    else if (meshes())
    {
        os  << "triangle meshes (" << shape_.mesh().nFaces()
            << " faces, " << meshes_[0].bvh().nodes().size()
            << " tree nodes) between pellets, ";
        if (hullRadius_ > 0)
        {
            os  << "exact " << shape_.type() << " contacts (rims: polygons"
                << " of " << hullRimAngles_.size() << " vertices, as the"
                << " mesh)";
        }
        else
        {
            os  << "mesh contacts";
        }
        os  << " with the container";
    }
    else
    {
        os  << "exact sphere contacts";
    }
}


// ************************************************************************* //
