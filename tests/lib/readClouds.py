#!/usr/bin/python3
"""Open an OpenFOAM case with VTK's vtkOpenFOAMReader (the reader inside
ParaView) and print, per lagrangian cloud, its particle count, its arrays and
their value ranges, as JSON: what a ParaView user would see.

Usage: readClouds.py <case> [time]
"""
import json
import os
import sys

import vtk


def read_clouds(case, time=None, per_particle=False):
    """Per cloud: particle count, arrays (components, range), bounds; with
    per_particle also "points" (x, y, z) and "values" {array: [tuple]}."""
    foam = os.path.join(case, os.path.basename(os.path.abspath(case)) + ".foam")
    if not os.path.exists(foam):
        open(foam, "w").close()
    r = vtk.vtkOpenFOAMReader()
    r.SetFileName(foam)
    r.UpdateInformation()
    # Lagrangian clouds are listed with the patches; enable them all
    for i in range(r.GetNumberOfPatchArrays()):
        r.SetPatchArrayStatus(r.GetPatchArrayName(i), 1)
    for i in range(r.GetNumberOfLagrangianArrays()):
        r.SetLagrangianArrayStatus(r.GetLagrangianArrayName(i), 1)
    times = r.GetTimeValues()
    if time is not None and times is not None:
        r.UpdateTimeStep(float(time))
    r.Update()
    out = r.GetOutput()

    clouds = {}
    for b in range(out.GetNumberOfBlocks()):
        name = out.GetMetaData(b).Get(vtk.vtkCompositeDataSet.NAME())
        if name != "lagrangian":
            continue
        lag = out.GetBlock(b)
        for c in range(lag.GetNumberOfBlocks()):
            cloud = lag.GetMetaData(c).Get(vtk.vtkCompositeDataSet.NAME())
            block = lag.GetBlock(c)
            arrays = {}
            pd = block.GetPointData()
            for a in range(pd.GetNumberOfArrays()):
                arr = pd.GetArray(a)
                arrays[arr.GetName()] = {
                    "components": arr.GetNumberOfComponents(),
                    "range": list(arr.GetRange(-1)),
                }
            clouds[cloud] = {
                "particles": block.GetNumberOfPoints(),
                "arrays": arrays,
                "bounds": list(block.GetBounds()),
            }
            if per_particle:
                n = block.GetNumberOfPoints()
                clouds[cloud]["points"] = [block.GetPoint(i) for i in range(n)]
                clouds[cloud]["values"] = {
                    pd.GetArray(a).GetName():
                        [pd.GetArray(a).GetTuple(i) for i in range(n)]
                    for a in range(pd.GetNumberOfArrays())
                }
    return clouds


if __name__ == "__main__":
    case = sys.argv[1]
    time = sys.argv[2] if len(sys.argv) > 2 else None
    print(json.dumps(read_clouds(case, time), indent=1, sort_keys=True))
