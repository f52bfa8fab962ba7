/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pelletShape.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::rbd::pelletShape> Foam::rbd::pelletShape::New
(
    const dictionary& dict
)
{
    const word shapeType(dict.get<word>("shape"));

    Info<< "Selecting pellet shape " << shapeType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(shapeType);

    if (!cstrIter.found())
    {
        FatalIOErrorInFunction(dict)
            << "Bad entry 'shape " << shapeType << ";' in " << dict.name()
            << nl << "    allowed: one of "
            << dictionaryConstructorTablePtr_->sortedToc() << nl
            << exit(FatalIOError);
    }

    return cstrIter()(dict);
}


// ************************************************************************* //
