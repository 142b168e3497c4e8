/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "setOperationRegion.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace meshless
{
    defineTypeNameAndDebug(setOperationRegion, 0);

    // One class, selectable under each operation's name
    addNamedToRunTimeSelectionTable
    (
        seedRegion, setOperationRegion, dictionary, union
    );
    addNamedToRunTimeSelectionTable
    (
        seedRegion, setOperationRegion, dictionary, intersection
    );
    addNamedToRunTimeSelectionTable
    (
        seedRegion, setOperationRegion, dictionary, difference
    );
}
}


const Foam::Enum<Foam::meshless::setOperationRegion::operation>
Foam::meshless::setOperationRegion::operationNames
({
    { operation::unionOp, "union" },
    { operation::intersectionOp, "intersection" },
    { operation::differenceOp, "difference" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::setOperationRegion::setOperationRegion
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    op_(operationNames.get("type", dict))
{
    // The operands as a list of dictionaries; each gets this dictionary as
    // parent so that errors in it name the file
    List<dictionary> dicts(dict.lookup("regions"));
    if (dicts.size() < 2)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'regions' has " << dicts.size() << " region(s):"
            << " expected a list of at least two region dictionaries"
            << exit(FatalIOError);
    }

    regions_.setSize(dicts.size());
    forAll(dicts, i)
    {
        dictionary operand(dict, dicts[i]);
        operand.name() =
            fileName::concat(dict.name(), "regions." + Foam::name(i), '.');
        regions_.set(i, seedRegion::New(operand, mesh));
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::boundBox Foam::meshless::setOperationRegion::bounds() const
{
    if (op_ == operation::differenceOp)
    {
        return regions_[0].bounds();
    }

    boundBox bb(regions_[0].bounds());
    for (label i = 1; i < regions_.size(); ++i)
    {
        const boundBox bi(regions_[i].bounds());
        if (op_ == operation::unionOp)
        {
            bb.add(bi);
        }
        else
        {
            bb.min() = max(bb.min(), bi.min());
            bb.max() = min(bb.max(), bi.max());
        }
    }
    return bb;
}


void Foam::meshless::setOperationRegion::inside
(
    const pointField& points,
    const labelUList& cells,
    boolList& in
) const
{
    regions_[0].inside(points, cells, in);

    boolList inI;
    for (label i = 1; i < regions_.size(); ++i)
    {
        regions_[i].inside(points, cells, inI);
        forAll(in, pointi)
        {
            switch (op_)
            {
                case operation::unionOp:
                    in[pointi] = in[pointi] || inI[pointi];
                    break;
                case operation::intersectionOp:
                    in[pointi] = in[pointi] && inI[pointi];
                    break;
                case operation::differenceOp:
                    in[pointi] = in[pointi] && !inI[pointi];
                    break;
            }
        }
    }
}

// ************************************************************************* //
