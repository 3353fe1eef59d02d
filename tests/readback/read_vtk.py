#!/usr/bin/env python3
"""modes.vtp and sensors.vtp read by VTK's own XML reader (Debian's python3-vtk9), as ParaView reads it,
and compared with modes.json of the same run: points, deflections, every mode's shape,
the frequencies, the links' polylines, the joints and the sections (the MMV report's
Table 1, docs/sources.md section 1). Then what a ParaView user does with it: Warp By
Vector on a mode and Tube with the section radius.

    read_vtk.py DIR [DIR ...]    each DIR holds a `modes --out` run (modes.vtp; the article's or HAM-SAS's) or a
                                 `place-sensors --out` run (sensors.vtp)
    read_vtk.py --run RUN.pvd RUN_DIR   `render --history RUN_DIR --out RUN.pvd` against
                                 the run's history.csv (its link tips at the frames' times)

sensors.vtp against channels.csv and test_geometry.uff's sibling placement.json: one
point per channel at its station, the measuring axis, the target modes' shapes.
"""
import csv
import xml.etree.ElementTree as ET
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


def check_warp(poly, array, what):
    """ParaView's Warp By Vector on `array` at scale 0.5 moves each point by half its vector."""
    warp = vtkWarpVector()
    warp.SetInputData(poly)
    warp.SetInputArrayToProcess(0, 0, 0, 0, array)
    warp.SetScaleFactor(0.5)
    warp.Update()
    moved, shape = warp.GetOutput(), poly.GetPointData().GetArray(array)
    for i in range(poly.GetNumberOfPoints()):
        p, q, u = poly.GetPoint(i), moved.GetPoint(i), shape.GetTuple3(i)
        check(all(close(q[c], p[c] + 0.5 * u[c], 1e-9) for c in range(3)), what(i))


def read_hamsas(d, js):
    """A HAM-SAS modes.vtp: each moving body a closed box of 8 corners and 6 faces
    (VTK's own normals point out of it), every mode's corner motion the body's
    translation plus its small rotation times the corner's offset from the box's centre,
    from modes.json's `shape`; then Warp By Vector as a ParaView user would."""
    where = f"{d}/modes.vtp"
    poly = read_poly(d / "modes.vtp")
    fd, pd = poly.GetFieldData(), poly.GetPointData()
    bodies = strings(fd, "body_names")
    moving = [b["body"] for b in js["modes"][0]["shape"]]
    check(bodies is not None and bodies[1:] == moving, f"{where}: body_names {bodies}, JSON's moving bodies {moving}")
    n = len(moving)
    check(poly.GetNumberOfPoints() == 8 * n and poly.GetNumberOfPolys() == 6 * n,
          f"{where}: {poly.GetNumberOfPoints()} points and {poly.GetNumberOfPolys()} faces for {n} bodies")
    index = pd.GetArray("body_index")
    centre = {}
    for i in range(poly.GetNumberOfPoints()):
        b = int(index.GetValue(i))
        c = centre.setdefault(b, [0.0, 0.0, 0.0])
        for k in range(3):
            c[k] += poly.GetPoint(i)[k] / 8
    # Closed and outward: the faces' signed volume is each box's volume, positive.
    from vtkmodules.vtkFiltersCore import vtkMassProperties, vtkTriangleFilter
    tri = vtkTriangleFilter()
    tri.SetInputData(poly)
    tri.Update()
    mass = vtkMassProperties()
    mass.SetInputData(tri.GetOutput())
    mass.Update()
    check(mass.GetVolume() > 0 and mass.GetSurfaceArea() > 0, f"{where}: the boxes enclose {mass.GetVolume()} m^3")
    hz = fd.GetArray("frequency_hz")
    check(hz is not None and hz.GetNumberOfTuples() == len(js["modes"]), f"{where}: frequency_hz per mode")
    for k, m in enumerate(js["modes"]):
        check(close(hz.GetValue(k), m["frequency_hz"]), f"{where}: mode {m['mode']} at {hz.GetValue(k)} Hz, JSON {m['frequency_hz']}")
        name = f"mode{m['mode']:02d}_" + (f"{m['frequency_hz']:.4g}Hz" if m["stable"] else "unstable")
        arr = pd.GetArray(name)
        check(arr is not None and arr.GetNumberOfComponents() == 3, f"{where}: no 3-component array {name}")
        if arr is None:
            continue
        for i in range(poly.GetNumberOfPoints()):
            b = int(index.GetValue(i))
            s = m["shape"][b - 1]
            t, w = s["translation"], s["rotation"]
            r = [poly.GetPoint(i)[c] - centre[b][c] for c in range(3)]
            want = (t[0] + w[1] * r[2] - w[2] * r[1], t[1] + w[2] * r[0] - w[0] * r[2], t[2] + w[0] * r[1] - w[1] * r[0])
            u = arr.GetTuple3(i)
            scale = max(1e-300, max(abs(x) for x in t) + max(abs(x) for x in w))
            check(all(abs(u[c] - want[c]) <= 1e-9 * scale for c in range(3)), f"{where}: {name} at corner {i} of {bodies[b]}: {u}, JSON {want}")
    check_warp(poly, f"mode01_{js['modes'][0]['frequency_hz']:.4g}Hz", lambda i: f"{where}: warped corner {i}")
    return len(js["modes"]), poly.GetNumberOfPoints()


def read(directory):
    d = Path(directory)
    if (d / "sensors.vtp").exists():
        return read_sensors(d)
    js = json.loads((d / "modes.json").read_text())
    if js.get("model") == "hamsas":
        return read_hamsas(d, js)
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
    check_warp(poly, f"mode01_{js['modes'][0]['frequency_hz']:.4g}Hz", lambda i: f"{where}: warped point {names[i]}")
    pd.SetActiveScalars("tube_radius_m")
    tube = vtkTubeFilter()
    tube.SetInputData(poly)
    tube.SetVaryRadiusToVaryRadiusByAbsoluteScalar()
    tube.SetNumberOfSides(8)
    tube.Update()
    check(tube.GetOutput().GetNumberOfPolys() + tube.GetOutput().GetNumberOfStrips() > 0, f"{where}: Tube made no surface")
    return len(js["modes"]), poly.GetNumberOfPoints()


def read_run(pvd, run_dir):
    """The collection's frames in time order, each a PolyData whose link tips are where
    history.csv has them at that time (frames at sample times), the first frame's
    displacement zero and each later one's its motion since."""
    pvd = Path(pvd)
    history = list(csv.DictReader(open(Path(run_dir) / "history.csv", newline="")))
    at = {round(float(r["time_s"]), 9): r for r in history}
    sets = ET.parse(pvd).getroot().find("Collection").findall("DataSet")
    times = [float(d.get("timestep")) for d in sets]
    check(len(sets) >= 2 and times == sorted(times), f"{pvd}: {len(sets)} frames, times {times[:4]}...")
    compared = 0
    first = None
    for d, t in zip(sets, times):
        poly = read_poly(pvd.parent / d.get("file"))
        where = f"{pvd}: frame at {t} s"
        check(close(poly.GetFieldData().GetArray("TimeValue").GetValue(0), t), f"{where}: TimeValue")
        n = poly.GetNumberOfPoints()
        pts = [poly.GetPoint(i) for i in range(n)]
        if first is None:
            first = pts
        disp = poly.GetPointData().GetArray("displacement_m")
        for i in range(n):
            moved = tuple(pts[i][c] - first[i][c] for c in range(3))
            check(all(abs(disp.GetTuple3(i)[c] - moved[c]) <= 1e-12 for c in range(3)), f"{where}: displacement of point {i}")
        row = at.get(round(t, 9))
        if row is None:
            continue
        bodies = strings(poly.GetFieldData(), "body_names")
        if bodies is not None:  # HAM-SAS: a body's corners' mean moves as its mass centre in history.csv
            index = poly.GetPointData().GetArray("body_index")
            for b, body in enumerate(bodies):
                col = body + "_x_m"
                corners = [i for i in range(n) if int(index.GetValue(i)) == b]
                if col not in row or not corners:
                    continue
                for c, axis in enumerate("xyz"):
                    moved = sum(pts[i][c] - first[i][c] for i in corners) / len(corners)
                    want = float(row[f"{body}_{axis}_m"]) - float(history[0][f"{body}_{axis}_m"])
                    check(abs(moved - want) <= 1e-6 * abs(want) + 1e-13,  # micrometre motions of metre-sized bodies
                          f"{where}: {body} moved {moved} m along {axis}, history.csv {want}")
                compared += 1
            continue
        links = strings(poly.GetFieldData(), "link_names")
        lines = poly.GetLines()
        lines.InitTraversal()
        from vtkmodules.vtkCommonCore import vtkIdList
        ids = vtkIdList()
        k = 0
        while lines.GetNextCell(ids):
            tip = pts[ids.GetId(ids.GetNumberOfIds() - 1)]
            col = links[k] + "_tip_"
            if col + "x_m" in row:
                want = (float(row[col + "x_m"]), float(row[col + "y_m"]))
                check(all(abs(tip[c] - want[c]) <= 1e-6 for c in range(2)), f"{where}: {links[k]} tip at {tip[:2]}, history.csv {want}")
                compared += 1
            k += 1
    check(compared >= 4, f"{pvd}: only {compared} tips or bodies compared with history.csv")
    return len(sets), compared


if len(sys.argv) == 4 and sys.argv[1] == "--run":
    frames, tips = read_run(sys.argv[2], sys.argv[3])
    print(f"{sys.argv[2]}: {frames} frames read back by VTK, {tips} link tips or bodies equal to history.csv's")
    sys.argv = sys.argv[:1]
for directory in sys.argv[1:]:
    modes, npoints = read(directory)
    print(f"{directory}: {modes} modes over {npoints} points read back by VTK")
if failures:
    print("\n".join(failures[:40]), file=sys.stderr)
    print(f"{len(failures)} mismatches", file=sys.stderr)
    sys.exit(1)
