/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "dictionaryChecks.H"
#include "error.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

template<class T>
void Foam::rbd::badEntry
(
    const dictionary& dict,
    const word& key,
    const T& value,
    const string& allowed
)
{
    FatalIOErrorInFunction(dict)
        << "Bad entry '" << key << ' ' << value << ";' in "
        << dict.name() << nl
        << "    allowed: " << allowed.c_str() << nl
        << exit(FatalIOError);

    ::exit(1);  // not reached: FatalIOError exits
}


// ************************************************************************* //
