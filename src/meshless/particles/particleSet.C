/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleSet.H"
#include "error.H"
#include <algorithm>

const Foam::word Foam::meshless::particleSet::positionsName("positions");


Foam::meshless::particleSet::particleSet(const word& name, const label dim)
:
    name_(name),
    dim_(dim),
    size_(0),
    id_(),
    nextId_(0),
    nOwned_(-1),
    replicated_(false),
    fields_()
{
    if (dim != 2 && dim != 3)
    {
        FatalErrorInFunction
            << "Particle set " << name << ": dimension " << dim
            << " is not supported, expected 2 or 3" << exit(FatalError);
    }
    addField(positionsName, particleField::kind::vector);
}


bool Foam::meshless::particleSet::found(const word& fieldName) const
{
    return fields_.count(fieldName) != 0;
}


Foam::meshless::particleField&
Foam::meshless::particleSet::field(const word& fieldName)
{
    return const_cast<particleField&>
    (
        static_cast<const particleSet&>(*this).field(fieldName)
    );
}


const Foam::meshless::particleField&
Foam::meshless::particleSet::field(const word& fieldName) const
{
    const auto iter = fields_.find(fieldName);
    if (iter == fields_.end())
    {
        FatalErrorInFunction
            << "Particle set " << name_ << " has no field " << fieldName
            << nl << "Fields: " << fieldNames() << exit(FatalError);
    }
    return *iter->second;
}


Foam::wordList Foam::meshless::particleSet::fieldNames() const
{
    wordList names(label(fields_.size()));
    label i = 0;
    for (const auto& f : fields_)
    {
        names[i++] = f.first;
    }
    return names;
}


Foam::meshless::particleField& Foam::meshless::particleSet::addField
(
    const word& fieldName,
    particleField::kind k
)
{
    auto iter = fields_.find(fieldName);
    if (iter != fields_.end())
    {
        if (iter->second->fieldKind() != k)
        {
            FatalErrorInFunction
                << "Particle set " << name_ << ": field " << fieldName
                << " exists as a "
                << particleField::kindNames[iter->second->fieldKind()]
                << ", requested as a " << particleField::kindNames[k]
                << exit(FatalError);
        }
        return *iter->second;
    }

    std::unique_ptr<particleField> f(new particleField(fieldName, k, dim_));
    f->resize(size_);
    particleField& ref = *f;
    fields_.emplace(fieldName, std::move(f));
    return ref;
}


Foam::meshless::particleField& Foam::meshless::particleSet::addScratchField
(
    const word& fieldName,
    particleField::kind k
)
{
    if (found(fieldName))
    {
        FatalErrorInFunction
            << "Particle set " << name_ << ": scratch field " << fieldName
            << " already exists" << exit(FatalError);
    }
    std::unique_ptr<particleField> f
    (
        new particleField(fieldName, k, dim_, false)
    );
    f->resize(size_);
    particleField& ref = *f;
    fields_.emplace(fieldName, std::move(f));
    return ref;
}


void Foam::meshless::particleSet::resize(const label n)
{
    id_.resize(n);
    for (label i = size_; i < n; ++i)
    {
        id_[i] = nextId_++;
    }
    for (auto& f : fields_)
    {
        f.second->resize(n);
    }
    size_ = n;
}


void Foam::meshless::particleSet::setIds(const std::vector<label>& ids)
{
    if (label(ids.size()) != size_)
    {
        FatalErrorInFunction
            << "Particle set " << name_ << " has " << size_
            << " particles, given " << ids.size() << " ids" << exit(FatalError);
    }
    id_ = ids;
    nextId_ = 0;
    for (const label id : id_)
    {
        nextId_ = std::max(nextId_, id + 1);
    }
}


void Foam::meshless::particleSet::setNextId(const label next)
{
    for (const label id : id_)
    {
        if (id >= next)
        {
            FatalErrorInFunction
                << "Particle set " << name_ << ": next id " << next
                << " is not above the existing id " << id
                << abort(FatalError);
        }
    }
    nextId_ = next;
}


Foam::label Foam::meshless::particleSet::appendCopies
(
    const std::vector<label>& from
)
{
    const label n0 = size_;
    const label nNew = label(from.size());
    resize(n0 + nNew);
    for (auto& f : fields_)
    {
        particleField& field = *f.second;
        const label nc = field.nComponents();
        double* d = field.data();
        for (label k = 0; k < nNew; ++k)
        {
            const double* src = d + size_t(from[k])*nc;
            double* dst = d + size_t(n0 + k)*nc;
            for (label c = 0; c < nc; ++c) dst[c] = src[c];
        }
    }
    return n0;
}


Foam::label Foam::meshless::particleSet::appendIds
(
    const label* ids,
    const label n
)
{
    const label n0 = size_;
    id_.resize(n0 + n);
    for (label k = 0; k < n; ++k) id_[n0 + k] = ids[k];
    for (auto& f : fields_) f.second->resize(n0 + n);
    size_ = n0 + n;
    return n0;
}


void Foam::meshless::particleSet::removeUnordered
(
    const std::vector<label>& indices
)
{
    // From the largest hole down: the last particle is then never one to
    // remove unless it is the hole itself
    label n = size_;
    for (auto it = indices.rbegin(); it != indices.rend(); ++it)
    {
        const label i = *it;
        --n;
        if (i == n) continue;
        id_[i] = id_[n];
        for (auto& f : fields_)
        {
            particleField& field = *f.second;
            const label nc = field.nComponents();
            double* d = field.data();
            for (label c = 0; c < nc; ++c) d[i*nc + c] = d[n*nc + c];
        }
    }
    truncate(n);
}


void Foam::meshless::particleSet::truncate(const label n)
{
    if (n > size_)
    {
        FatalErrorInFunction
            << "Particle set " << name_ << " has " << size_
            << " particles, cannot truncate to " << n << abort(FatalError);
    }
    id_.resize(n);
    for (auto& f : fields_) f.second->resize(n);
    size_ = n;
    nOwned_ = -1;
}


Foam::label Foam::meshless::particleSet::removeMarked
(
    const std::vector<char>& remove
)
{
    if (label(remove.size()) != size_)
    {
        FatalErrorInFunction
            << "Particle set " << name_ << " has " << size_
            << " particles but the removal marks " << remove.size()
            << abort(FatalError);
    }
    label kept = 0;
    for (label i = 0; i < size_; ++i)
    {
        if (!remove[i]) id_[kept++] = id_[i];
    }
    if (kept == size_) return 0;
    for (auto& f : fields_)
    {
        particleField& field = *f.second;
        const label nc = field.nComponents();
        double* d = field.data();
        label j = 0;
        for (label i = 0; i < size_; ++i)
        {
            if (remove[i]) continue;
            if (j != i)
            {
                double* dst = d + size_t(j)*nc;
                const double* src = d + size_t(i)*nc;
                for (label c = 0; c < nc; ++c) dst[c] = src[c];
            }
            ++j;
        }
        field.resize(kept);
    }
    const label removed = size_ - kept;
    id_.resize(kept);
    size_ = kept;
    return removed;
}


void Foam::meshless::particleSet::reorder(const std::vector<label>& order)
{
    if (label(order.size()) != size_)
    {
        FatalErrorInFunction
            << "Particle set " << name_ << " has " << size_
            << " particles but the ordering has " << order.size()
            << abort(FatalError);
    }
    for (auto& f : fields_)
    {
        f.second->reorder(order, scratch_);
    }

    if (labelScratch_.size() < id_.size())
    {
        labelScratch_.resize(id_.size());
    }
    for (label i = 0; i < size_; ++i)
    {
        labelScratch_[i] = id_[order[i]];
    }
    std::copy(labelScratch_.begin(), labelScratch_.begin() + size_, id_.begin());
}


Foam::label Foam::meshless::particleSet::findId(const label id) const
{
    const auto iter = std::find(id_.begin(), id_.end(), id);
    return iter == id_.end() ? -1 : label(iter - id_.begin());
}
