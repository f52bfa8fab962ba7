/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "contactDispatch.H"
#include "sphereContacts.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::rbd::contactDispatch::generatorTable::generatorTable()
:
    pairs(),
    containers()
{
    registerPair(sphereGeometry, sphereGeometry, &contactDispatch::spherePair);
    registerPair(meshGeometry, meshGeometry, &contactDispatch::meshPair);
    registerPair(prismGeometry, prismGeometry, &contactDispatch::prismPair);

    containers[sphereGeometry] = &contactDispatch::sphereContainer;
    containers[meshGeometry] = &contactDispatch::meshContainer;
    containers[prismGeometry] = &contactDispatch::prismContainer;
}


void Foam::rbd::contactDispatch::generatorTable::registerPair
(
    const geometry a,
    const geometry b,
    const pairGenerator generate
)
{
    pairs[a][b] = pairEntry{generate, false};
    if (a != b)
    {
        pairs[b][a] = pairEntry{generate, true};
    }
}


const Foam::rbd::contactDispatch::generatorTable&
Foam::rbd::contactDispatch::table()
{
    static const generatorTable theTable;
    return theTable;
}


void Foam::rbd::contactDispatch::setMaterial
(
    DynamicList<contact>& contacts,
    const label start,
    const scalar e,
    const scalar mu
)
{
    for (label ci = start; ci < contacts.size(); ++ci)
    {
        contacts[ci].e = e;
        contacts[ci].mu = mu;
    }
}


// * * * * * * * * * * * * * * * * Generators  * * * * * * * * * * * * * * * //

void Foam::rbd::contactDispatch::spherePair
(
    const label i, const rigidBody& bi,
    const label k, const rigidBody& bk,
    DynamicList<contact>& contacts, const label
) const
{
    contact c;
    if (sphereContacts::sphereSphere(i, bi, rb_, k, bk, rb_, band_, c))
    {
        contacts.append(c);
    }
}


void Foam::rbd::contactDispatch::meshPair
(
    const label i, const rigidBody& bi,
    const label k, const rigidBody& bk,
    DynamicList<contact>& contacts, const label thread
) const
{
    meshes_[thread].meshMesh(i, bi, k, bk, contacts);
}


void Foam::rbd::contactDispatch::prismPair
(
    const label i, const rigidBody& bi,
    const label k, const rigidBody& bk,
    DynamicList<contact>& contacts, const label thread
) const
{
    prisms_[thread].prismPrism(i, bi, k, bk, contacts);
}


void Foam::rbd::contactDispatch::sphereContainer
(
    const label i, const rigidBody& bi,
    DynamicList<contact>& contacts
) const
{
    sphereContacts::sphereTube(i, bi, rb_, tube_, band_, contacts);
}


void Foam::rbd::contactDispatch::meshContainer
(
    const label i, const rigidBody& bi,
    DynamicList<contact>& contacts
) const
{
    meshes_[0].meshTube(i, bi, tube_, contacts);
}


void Foam::rbd::contactDispatch::prismContainer
(
    const label i, const rigidBody& bi,
    DynamicList<contact>& contacts
) const
{
    prisms_[0].prismTube(i, bi, tube_, contacts);
}


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
    geometry_(sphereGeometry),
    restitution_(restitution),
    friction_(friction),
    rb_(shape.boundingRadius()),
    band_(band),
    meshes_(),
    prism_(),
    prisms_()
{
    const word model(pairModel(shape_, contactModel));
    const label nThreads = max(threads, label(1));
    if (model == "prism")
    {
        geometry_ = prismGeometry;
        prism_ = shape_.prism();
        prisms_.setSize(nThreads);
        forAll(prisms_, t)
        {
            prisms_.set(t, new prismContacts(prism_(), band_));
        }
    }
    else if (model == "mesh")
    {
        geometry_ = meshGeometry;
        meshes_.setSize(nThreads);
        forAll(meshes_, t)
        {
            meshes_.set(t, new meshContacts(shape_.mesh(), band_));
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
    const autoPtr<prismProfile> prism(shape.prism());
    const bool hasPrism = prism.valid();
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

    // auto: the exact solid, but for a cylinder with holes off its axis.
    // Its pairs unreduced (prismContacts), the rings stayed within 0.5 %
    // of d on 34 beds and the soak's hooked rings, and packed 8 to 120
    // times faster than on their meshes; one bed of 8 cylinders with
    // four 2 mm holes reached 0.53 %, so those keep their meshes
    // (docs/exactContacts.md, "Thirty-fifth session")
    if (hasPrism && !prism->hasOffAxisHole())
    {
        return "prism";
    }
    return "mesh";
}


Foam::rbd::contactDispatch::pairEntry Foam::rbd::contactDispatch::pairOf
(
    const geometry a,
    const geometry b
)
{
    return table().pairs[a][b];
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
    const pairEntry& entry = table().pairs[geometry_][geometry_];
    if (!entry.generate)
    {
        FatalErrorInFunction
            << "no narrow phase registered for pellets of geometry "
            << label(geometry_) << " against each other"
            << exit(FatalError);
    }
    if (!entry.reversed)
    {
        (this->*entry.generate)(i, bi, k, bk, contacts, thread);
    }
    else
    {
        (this->*entry.generate)(k, bk, i, bi, contacts, thread);
        for (label ci = start; ci < contacts.size(); ++ci)
        {
            contacts[ci] = reversed(contacts[ci]);
        }
    }
    setMaterial(contacts, start, restitution_, friction_);
}


void Foam::rbd::contactDispatch::pelletContainer
(
    const label i,
    const rigidBody& bi,
    DynamicList<contact>& contacts
) const
{
    const label start = contacts.size();
    const containerGenerator generate = table().containers[geometry_];
    if (!generate)
    {
        FatalErrorInFunction
            << "no narrow phase registered for pellets of geometry "
            << label(geometry_) << " against the container"
            << exit(FatalError);
    }
    (this->*generate)(i, bi, contacts);
    setMaterial(contacts, start, tube_.restitution(), tube_.friction());
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
            << " tree nodes) between pellets and with the container";
    }
    else
    {
        os  << "exact sphere contacts";
    }
}


// ************************************************************************* //
