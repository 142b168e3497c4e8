/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleSetState.H"
#include "error.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::meshless::particleSetState::save
(
    particleSet& set,
    const std::vector<const particleField*>& skip
)
{
    set_ = &set;
    const wordList names(set.fieldNames());
    fields_.clear();
    data_.resize(names.size());
    forAll(names, k)
    {
        particleField& f = set.field(names[k]);
        if (std::find(skip.begin(), skip.end(), &f) != skip.end()) continue;
        const size_t n = size_t(f.size())*f.nComponents();
        std::vector<double>& d = data_[fields_.size()];
        d.resize(n);
        std::copy(f.data(), f.data() + n, d.begin());
        fields_.push_back(&f);
    }
    ids_ = set.ids();
}


void Foam::meshless::particleSetState::restore()
{
    if (!set_) return;
    if (set_->ids() != ids_)
    {
        FatalErrorInFunction
            << "Particles of " << set_->name() << " changed since their state"
            << " was saved (" << ids_.size() << " then, " << set_->size()
            << " now, or reordered): the state cannot be set back"
            << exit(FatalError);
    }
    forAll(fields_, k)
    {
        std::copy(data_[k].begin(), data_[k].end(), fields_[k]->data());
    }
}


// ************************************************************************* //
