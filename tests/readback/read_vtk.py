#!/usr/bin/env python3
"""modes.vtp and sensors.vtp read by VTK's own XML reader (Debian's python3-vtk9), as ParaView reads it,
and compared with modes.json of the same run: points, deflections, every mode's shape,
the frequencies, the links' polylines, the joints and the sections (the MMV report's
Table 1, docs/sources.md section 1). Then what a ParaView user does with it: Warp By
Vector on a mode and Tube with the section radius.

    read_vtk.py DIR [DIR ...]    each DIR holds a `modes --out` run (modes.vtp) or a
                                 `place-sensors --out` run (sensors.vtp)

sensors.vtp against channels.csv and test_geometry.uff's sibling placement.json: one
point per channel at its station, the measuring axis, the target modes' shapes.
"""
import csv
import json
import math
import sys
from pathlib import Path

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkFiltersCore import vtkTubeFilter
from vtkmodules.vtkFiltersGeneral import vtkWarpVector

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(a), abs(b))


def strings(data, name):
    arr = data.GetAbstractArray(name)
    return [arr.GetValue(i) for i in range(arr.GetNumberOfValues())] if arr else None


def read_poly(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    check(reader.GetErrorCode() == 0, f"{path}: the reader reported error {reader.GetErrorCode()}")
    return reader.GetOutput()


def read_sensors(d):
    where = f"{d}/sensors.vtp"
    poly = read_poly(d / "sensors.vtp")
    placement = json.loads((d / "placement.json").read_text())
    with open(d / "channels.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    check(poly.GetNumberOfPoints() == len(rows) and poly.GetNumberOfVerts() == len(rows),
          f"{where}: {poly.GetNumberOfPoints()} points, {poly.GetNumberOfVerts()} verts for {len(rows)} channels")
    at = {c["station"]: c for c in placement["chosen"]}
    pd = poly.GetPointData()
    labels = strings(poly.GetFieldData(), "channels")
    for i, row in enumerate(rows):
        chosen = at.get(row["station"])
        check(chosen is not None, f"{where}: channel {row['channel']} at {row['station']}, not a chosen station")
        if chosen is None:
            continue
        x = poly.GetPoint(i)
        want = (chosen["world_x_m"], chosen["world_y_m"], chosen["world_z_m"])
        check(all(close(x[k], want[k]) for k in range(3)), f"{where}: channel {row['channel']} at {x}, JSON {want}")
        u = pd.GetArray("direction").GetTuple3(i)
        w = tuple(float(row[f"direction_{a}"]) for a in "xyz")
        check(all(abs(u[k] - w[k]) <= 5e-7 for k in range(3)) and close(math.hypot(*u), 1.0, 1e-9),
              f"{where}: channel {row['channel']} axis {u}, channels.csv {w}")
        check(int(pd.GetArray("channel").GetValue(i)) == int(row["channel"]) and int(pd.GetArray("node").GetValue(i)) == int(row["node"]),
              f"{where}: channel and node of point {i}")
        check(labels[i] == f"{row['station']} {row['axis']}", f"{where}: label {labels[i]} for {row['station']} {row['axis']}")
        check(int(pd.GetArray("kept_from_scene").GetValue(i)) == int(chosen["fixed"]),
              f"{where}: kept_from_scene of channel {row['channel']} is not placement.json's fixed")
    hz = poly.GetFieldData().GetArray("target_frequency_hz")
    for j, (m, f) in enumerate(zip(placement["target_modes"], placement["target_frequencies_hz"])):
        check(close(hz.GetValue(j), f), f"{where}: target mode {m} at {hz.GetValue(j)} Hz, JSON {f}")
        check(pd.GetArray(f"mode{m:02d}_{f:.4g}Hz") is not None, f"{where}: no array for target mode {m}")
    return len(placement["target_modes"]), poly.GetNumberOfPoints()


def read(directory):
    d = Path(directory)
    if (d / "sensors.vtp").exists():
        return read_sensors(d)
    js = json.loads((d / "modes.json").read_text())
    poly = read_poly(d / "modes.vtp")
    where = f"{d}/modes.vtp"

    points = js["equilibrium"]["points"]
    names = [p["name"] for p in points]
    check(poly.GetNumberOfPoints() == len(points), f"{where}: {poly.GetNumberOfPoints()} points, JSON {len(points)}")
    pd = poly.GetPointData()
    deflection = pd.GetArray("deflection_m")
    for i, p in enumerate(points):
        x = poly.GetPoint(i)
        want = (p["x_m"], p["y_m"], p.get("z_m", 0.0))
        check(all(close(x[k], want[k]) for k in range(3)), f"{where}: point {p['name']} at {x}, JSON {want}")
        dv = deflection.GetTuple3(i)
        dwant = (p["deflection_x_m"], p["deflection_y_m"], p.get("deflection_z_m", 0.0))
        check(all(close(dv[k], dwant[k]) for k in range(3)), f"{where}: deflection of {p['name']}")

    fd = poly.GetFieldData()
    hz = fd.GetArray("frequency_hz")
    check(hz is not None and hz.GetNumberOfTuples() == len(js["modes"]), f"{where}: frequency_hz per mode")
    for k, m in enumerate(js["modes"]):
        check(close(hz.GetValue(k), m["frequency_hz"]), f"{where}: mode {m['number']} at {hz.GetValue(k)} Hz, JSON {m['frequency_hz']}")
        name = f"mode{m['number']:02d}_{m['frequency_hz']:.4g}Hz"
        arr = pd.GetArray(name)
        check(arr is not None and arr.GetNumberOfComponents() == 3, f"{where}: no 3-component array {name}")
        if arr is None:
            continue
        for s in m["shape"]:
            u = arr.GetTuple3(names.index(s["point"]))
            want = (s["ux"], s["uy"], s.get("uz", 0.0))
            check(all(close(u[c], want[c]) for c in range(3)), f"{where}: {name} at {s['point']}: {u}, JSON {want}")

    links = [l["name"] for l in js["model"]["links"]]
    check(strings(fd, "link_names") == links, f"{where}: link_names {strings(fd, 'link_names')}, JSON {links}")
    check(poly.GetNumberOfLines() == len(links), f"{where}: {poly.GetNumberOfLines()} lines for {len(links)} links")
    lines = poly.GetLines()
    lines.InitTraversal()
    from vtkmodules.vtkCommonCore import vtkIdList
    ids = vtkIdList()
    k = 0
    while lines.GetNextCell(ids):
        chain = [names[ids.GetId(j)] for j in range(ids.GetNumberOfIds())]
        link = links[k]
        check(chain[0] == link + ".root" and chain[-1] == link + ".tip" and all(c.startswith(link + ".") for c in chain),
              f"{where}: line {k} runs {chain[0]} .. {chain[-1]}, not {link}.root .. {link}.tip")
        k += 1
    joints = [n for n in names if "." not in n]
    check(poly.GetNumberOfVerts() == len(joints), f"{where}: {poly.GetNumberOfVerts()} verts for joints {joints}")

    # The sections of the MMV report's Table 1: link 1 a 7.62 x 2.54 cm tube, link 2 a
    # 3.81 x 1.27 cm bar (depth in the bending plane, width out of it).
    depth, width = pd.GetArray("section_depth_m"), pd.GetArray("section_width_m")
    for link, h, b in (("link1", 0.0254, 0.0762), ("link2", 0.0127, 0.0381)):
        if link + ".root" in names:
            i = names.index(link + ".root")
            check(close(depth.GetValue(i), h, 1e-9) and close(width.GetValue(i), b, 1e-9),
                  f"{where}: {link} section {depth.GetValue(i)} x {width.GetValue(i)} m, Table 1 {h} x {b}")

    # ParaView's use: Warp By Vector with mode 1 moves each point by its shape; Tube
    # with the section radius gives a surface.
    first = f"mode01_{js['modes'][0]['frequency_hz']:.4g}Hz"
    warp = vtkWarpVector()
    warp.SetInputData(poly)
    warp.SetInputArrayToProcess(0, 0, 0, 0, first)
    warp.SetScaleFactor(0.5)
    warp.Update()
    shape = pd.GetArray(first)
    moved = warp.GetOutput()
    for i in range(poly.GetNumberOfPoints()):
        p, q, u = poly.GetPoint(i), moved.GetPoint(i), shape.GetTuple3(i)
        check(all(close(q[c], p[c] + 0.5 * u[c], 1e-9) for c in range(3)), f"{where}: warped point {names[i]}")
    pd.SetActiveScalars("tube_radius_m")
    tube = vtkTubeFilter()
    tube.SetInputData(poly)
    tube.SetVaryRadiusToVaryRadiusByAbsoluteScalar()
    tube.SetNumberOfSides(8)
    tube.Update()
    check(tube.GetOutput().GetNumberOfPolys() + tube.GetOutput().GetNumberOfStrips() > 0, f"{where}: Tube made no surface")
    return len(js["modes"]), poly.GetNumberOfPoints()


for directory in sys.argv[1:]:
    modes, npoints = read(directory)
    print(f"{directory}: {modes} modes over {npoints} points read back by VTK")
if failures:
    print("\n".join(failures[:40]), file=sys.stderr)
    print(f"{len(failures)} mismatches", file=sys.stderr)
    sys.exit(1)
