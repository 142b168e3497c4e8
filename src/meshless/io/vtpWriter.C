/*---------------------------------------------------------------------------*\
  meshlessFoam: meshless fluid-structure interaction inside OpenFOAM
\*---------------------------------------------------------------------------*/

// VTK first: after OpenFOAM's headers 'vtk' is ambiguous with Foam::vtk
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include "vtpWriter.H"
#include "atomicTimeWriter.H"
#include "OSspecific.H"
#include "OFstream.H"
#include "error.H"
#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

namespace
{

//- Sync a completely written file and rename it into place
void commitFile(const Foam::fileName& tmp, const Foam::fileName& file)
{
    using namespace Foam;
    meshless::atomicTimeWriter::syncPath(tmp);
    if (::rename(tmp.c_str(), file.c_str()) != 0)
    {
        FatalErrorInFunction
            << "Cannot rename " << tmp << " to " << file << ": "
            << std::strerror(errno) << exit(FatalError);
    }
    meshless::atomicTimeWriter::syncPath(file.path());
}

} // End anonymous namespace


void Foam::meshless::vtpWriter::write
(
    const particleSet& set,
    const fileName& dir,
    const word& timeName,
    const scalar zPlane
)
{
    const label n = set.size();
    const label dim = set.dim();
    const particleField& x = set.positions();

    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n);
    auto verts = vtkSmartPointer<vtkCellArray>::New();
    for (label i = 0; i < n; ++i)
    {
        points->SetPoint(i, x(i, 0), x(i, 1), dim == 3 ? x(i, 2) : zPlane);
        const vtkIdType id = i;
        verts->InsertNextCell(1, &id);
    }

    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetVerts(verts);

    auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
    ids->SetName("id");
    ids->SetNumberOfTuples(n);
    for (label i = 0; i < n; ++i) ids->SetValue(i, set.ids()[i]);
    poly->GetPointData()->AddArray(ids);

    for (const word& name : set.fieldNames())
    {
        if (name == particleSet::positionsName) continue;
        const particleField& f = set.field(name);
        if (!f.written()) continue;
        const label nc = f.nComponents();

        // Vectors as 3 components and tensors as 9, as ParaView expects
        const bool isVector = f.fieldKind() == particleField::kind::vector;
        const bool isTensor = f.fieldKind() == particleField::kind::tensor;
        const int outNc = isVector ? 3 : isTensor ? 9 : 1;

        auto arr = vtkSmartPointer<vtkDoubleArray>::New();
        arr->SetName(name.c_str());
        arr->SetNumberOfComponents(outNc);
        arr->SetNumberOfTuples(n);
        double buf[9];
        for (label i = 0; i < n; ++i)
        {
            std::fill(buf, buf + 9, 0.0);
            if (nc == outNc)
            {
                for (label c = 0; c < nc; ++c) buf[c] = f(i, c);
            }
            else if (isVector)      // 2D vector
            {
                buf[0] = f(i, 0);
                buf[1] = f(i, 1);
            }
            else                    // 2D tensor into the 3x3 layout
            {
                buf[0] = f(i, 0);
                buf[1] = f(i, 1);
                buf[3] = f(i, 2);
                buf[4] = f(i, 3);
            }
            arr->SetTuple(i, buf);
        }
        poly->GetPointData()->AddArray(arr);
    }

    const fileName bodyDir = dir/set.name();
    mkDir(bodyDir);
    const word fileBase(set.name() + "_" + timeName + ".vtp");
    const fileName file = bodyDir/fileBase;

    // Written under a hidden name, synced and renamed: a killed run leaves
    // no partial .vtp (the collection below skips hidden names)
    const fileName tmpFile = bodyDir/("." + fileBase + ".incomplete");
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetFileName(tmpFile.c_str());
    writer->SetInputData(poly);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    if (writer->Write() != 1)
    {
        FatalErrorInFunction
            << "VTK could not write " << tmpFile << exit(FatalError);
    }
    commitFile(tmpFile, file);

    // The collection, from the files present (restart- and purge-proof)
    const std::string prefix = set.name() + "_";
    std::vector<std::pair<double, std::string>> entries;
    for (const fileName& f : readDir(bodyDir, fileName::FILE))
    {
        if (f.hasExt("vtp") && f.find(prefix) == 0)
        {
            const std::string t =
                f.substr(prefix.size(), f.size() - prefix.size() - 4);
            entries.emplace_back(std::strtod(t.c_str(), nullptr), f);
        }
    }
    std::sort(entries.begin(), entries.end());

    // The collection replaced atomically: a killed run leaves the old one
    // or the new one, never a truncated one
    const fileName pvdFile = dir/(set.name() + ".pvd");
    const fileName pvdTmp = dir/("." + set.name() + ".pvd.incomplete");
    {
        OFstream pvd(pvdTmp);
        pvd << "<?xml version=\"1.0\"?>" << nl
            << "<VTKFile type=\"Collection\" version=\"0.1\">" << nl
            << "<Collection>" << nl;
        for (const auto& e : entries)
        {
            pvd << "  <DataSet timestep=\"" << e.first << "\" file=\""
                << set.name() << "/" << e.second.c_str() << "\"/>" << nl;
        }
        pvd << "</Collection>" << nl << "</VTKFile>" << nl;
        if (!pvd.good())
        {
            FatalErrorInFunction
                << "Failed writing " << pvdTmp << exit(FatalError);
        }
    }
    commitFile(pvdTmp, pvdFile);
}
