/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "pTraits.H"

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::bsmsTransition::downsample
(
    const UList<Type>& fine
) const
{
    if (fine.size() != nFine_)
    {
        FatalErrorInFunction
            << "Field of " << fine.size() << " values for a level of "
            << nFine_ << " nodes" << exit(FatalError);
    }
    tmp<Field<Type>> tcoarse(new Field<Type>(nCoarse_));
    downsample
    (
        reinterpret_cast<const scalar*>(fine.cdata()),
        reinterpret_cast<scalar*>(tcoarse.ref().data()),
        pTraits<Type>::nComponents
    );
    return tcoarse;
}


template<class Type>
Foam::tmp<Foam::Field<Type>> Foam::bsmsTransition::upsample
(
    const UList<Type>& coarse
) const
{
    if (coarse.size() != nCoarse_)
    {
        FatalErrorInFunction
            << "Field of " << coarse.size() << " values for a level of "
            << nCoarse_ << " nodes" << exit(FatalError);
    }
    tmp<Field<Type>> tfine(new Field<Type>(nFine_));
    upsample
    (
        reinterpret_cast<const scalar*>(coarse.cdata()),
        reinterpret_cast<scalar*>(tfine.ref().data()),
        pTraits<Type>::nComponents
    );
    return tfine;
}


// ************************************************************************* //
