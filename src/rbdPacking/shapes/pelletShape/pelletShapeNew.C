/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pelletShape.H"
#include "dictionaryChecks.H"

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
            << nl << "    allowed: "
            << inWords(dictionaryConstructorTablePtr_->sortedToc()).c_str()
            << nl
            << exit(FatalIOError);
    }

    // The meshing (CGAL) may refuse a shape whose entries passed their
    // checks (fifty holes of 0.5 mm: their polygons cross): a clear error,
    // not an abort
    try
    {
        return cstrIter()(dict);
    }
    catch (const Foam::error&)
    {
        throw;
    }
    catch (const std::exception& e)
    {
        std::string what(e.what());
        what = what.substr(0, what.find('\n'));
        FatalIOErrorInFunction(dict)
            << "Bad pellet shape in " << dict.name() << nl
            << "    the " << shapeType << " these entries describe cannot be"
            << " meshed (" << what.c_str() << ")" << nl
            << "    allowed: a shape whose features fit (fewer or larger "
            << "holes or lobes, more faces)" << nl
            << exit(FatalIOError);
    }
    return nullptr;
}


// ************************************************************************* //
