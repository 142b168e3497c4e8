/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bodyModel.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(bodyModel, 0);
    defineRunTimeSelectionTable(bodyModel, dictionary);
}
}


Foam::meshless::bodyModel::bodyModel
(
    particleBody& body,
    const dictionary& dict
)
:
    body_(body),
    dict_(dict)
{}


const Foam::Enum<Foam::meshless::bodyModel::modelRole>
Foam::meshless::bodyModel::modelRoleNames
({
    { modelRole::fluid, "fluid" },
    { modelRole::solid, "solid" },
    { modelRole::kinematic, "kinematic" },
    { modelRole::wall, "wall" },
});


Foam::HashTable<Foam::meshless::bodyModel::modelRole>&
Foam::meshless::bodyModel::roleTable()
{
    static HashTable<modelRole> table;
    return table;
}


Foam::wordList Foam::meshless::bodyModel::modelsOf(const modelRole role)
{
    DynamicList<word> names;
    forAllConstIters(roleTable(), iter)
    {
        if (iter.val() == role) names.append(iter.key());
    }
    wordList sorted(names);
    Foam::sort(sorted);
    return sorted;
}
