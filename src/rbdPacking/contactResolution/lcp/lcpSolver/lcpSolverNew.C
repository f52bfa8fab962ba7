/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "lcpSolver.H"
#include "error.H"
#include "dictionaryChecks.H"

// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::rbd::lcpSolver> Foam::rbd::lcpSolver::New
(
    const dictionary& dict
)
{
    const word solverType(selectedType(dict));

    Info<< "Selecting LCP solver " << solverType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(solverType);

    if (!cstrIter.found())
    {
        // (FatalIOErrorInLookup would print the table in list syntax)
        FatalIOErrorInFunction(dict)
            << "Unknown lcpSolver type " << solverType << " in "
            << dict.name() << nl << "    Valid lcpSolver types: "
            << inWords(dictionaryConstructorTablePtr_->sortedToc()).c_str()
            << nl << exit(FatalIOError);
    }

    return autoPtr<lcpSolver>
    (
        cstrIter()(subDictOrEmpty(dict, solverType + "Coeffs"))
    );
}


Foam::word Foam::rbd::lcpSolver::selectedType(const dictionary& dict)
{
    return dict.getOrDefault<word>("lcpSolver", "blockPivoting");
}


Foam::wordList Foam::rbd::lcpSolver::coeffsNames()
{
    wordList names(dictionaryConstructorTablePtr_->sortedToc());
    for (word& name : names)
    {
        name += "Coeffs";
    }
    return names;
}


// ************************************************************************* //
