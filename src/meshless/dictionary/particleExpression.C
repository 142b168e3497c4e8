/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleExpression.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshless::particleExpression::particleExpression
(
    const label n,
    const dictionary& dict
)
:
    expressions::fieldExpr::parseDriver(n, dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::particleExpression::setPositions
(
    const word& name,
    const vectorField& X
)
{
    variables_.clear();
    variables_.set(name, expressions::exprResult(X));
    addVariables(variableStrings_, false);
}


void Foam::meshless::particleExpression::setPositionsAndTime
(
    const vectorField& X,
    const scalar t
)
{
    variables_.clear();
    variables_.set("X", expressions::exprResult(X));
    variables_.set("t", expressions::exprResult(scalarField(X.size(), t)));
    addVariables(variableStrings_, false);
}


void Foam::meshless::particleExpression::evaluate
(
    const dictionary& dict,
    const particleField& X0,
    particleField& result
)
{
    const label n = X0.size();
    const label dim = X0.nComponents();

    vectorField X(n, Zero);
    for (label i = 0; i < n; ++i)
    {
        for (label c = 0; c < dim; ++c) X[i][c] = X0(i, c);
    }
    const tmp<vectorField> tvalues = evaluate(dict, X);
    const vectorField& values = tvalues();
    for (label i = 0; i < n; ++i)
    {
        for (label c = 0; c < dim; ++c) result(i, c) = values[i][c];
    }
}


Foam::tmp<Foam::vectorField> Foam::meshless::particleExpression::evaluate
(
    const dictionary& dict,
    const vectorField& X,
    const scalar* time
)
{
    const label n = X.size();
    particleExpression driver(n, dict);
    if (time) driver.setPositionsAndTime(X, *time);
    else driver.setPositions("X", X);

    const expressions::exprString expr(dict.get<string>("expression"));
    driver.parse(expr);

    if (!driver.result().isType<vector>())
    {
        FatalIOErrorInFunction(dict)
            << "expression \"" << expr << "\" does not give a vector per"
            << " particle (it gives " << driver.result().valueType() << ")"
            << exit(FatalIOError);
    }

    tmp<vectorField> tvalues = driver.getResult<vector>(false);
    if (tvalues().size() != n)
    {
        FatalIOErrorInFunction(dict)
            << "expression \"" << expr << "\" gave " << tvalues().size()
            << " values for " << n << " particles" << exit(FatalIOError);
    }
    return tvalues;
}


// ************************************************************************* //
