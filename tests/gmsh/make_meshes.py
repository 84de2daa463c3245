"""Make the Gmsh meshes of tests/gmsh.rs with the gmsh Python package (pip install gmsh).

Run from this folder: `python make_meshes.py`. The .msh files it writes are committed, so the
tests need no Gmsh; rerun it only to change them. Every mesh is format 4.1.

- hertz-blocks.msh (ASCII) and hertz-blocks-binary.msh: the two blocks of the built-in
  example `hertz` on the example's own mesh lines, one structured quadrilateral per cell,
  physical surfaces "cylinder" and "block", physical curves "contact", "top", "surface",
  "base". The same mesh as the example, so the same pressures to round-off.
- hertz-arc.msh and hertz-arc-order2.msh: the cylinder as a real arc of radius 500 mm about
  (0, 500) (the example gives that curvature as `contact.initial_shape` on a flat block);
  order 1, and order 2 (9-node quadrangles, the arcs as parabolas through their mid nodes).
- lame-order2.msh: the built-in example `lame` (a quarter ring, radii 100 and 200 mm) on its
  2 x 2 mesh, 9-node quadrangles; physical curves "inner", "outer", "x_axis", "z_axis".
- lame-triangles.msh: the same ring in triangles (wearfem refuses them).
- two-blocks-hanging.msh: two squares side by side meshed 2 x 2 and 3 x 3 without sharing
  their common side's nodes (not conforming).
"""
import math

import gmsh


def start(name):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
    gmsh.model.add(name)


def grid(xs, zs, bottom_center=None):
    """A structured grid of quadrangles on the lines xs × zs, one plane surface per cell.
    With `bottom_center`, the bottom row lies on the circle about it through (0, zs[0])."""
    geo = gmsh.model.geo
    radius = None if bottom_center is None else abs(bottom_center[1] - zs[0])

    def z_at(i, j):
        if j == 0 and radius is not None:
            return bottom_center[1] - math.sqrt(radius**2 - xs[i] ** 2)
        return zs[j]

    point = {(i, j): geo.addPoint(xs[i], z_at(i, j), 0) for i in range(len(xs)) for j in range(len(zs))}
    center = geo.addPoint(*bottom_center, 0) if radius is not None else None
    horizontal, vertical = {}, {}
    for j in range(len(zs)):
        for i in range(len(xs) - 1):
            a, b = point[i, j], point[i + 1, j]
            arc = j == 0 and center is not None
            horizontal[i, j] = geo.addCircleArc(a, center, b) if arc else geo.addLine(a, b)
    for j in range(len(zs) - 1):
        for i in range(len(xs)):
            vertical[i, j] = geo.addLine(point[i, j], point[i, j + 1])
    surfaces = []
    for j in range(len(zs) - 1):
        for i in range(len(xs) - 1):
            loop = geo.addCurveLoop(
                [horizontal[i, j], vertical[i + 1, j], -horizontal[i, j + 1], -vertical[i, j]]
            )
            surfaces.append(geo.addPlaneSurface([loop]))
    # The geo kernel's own mesh constraints: those set through gmsh.model.mesh would be lost
    # at the next geo.synchronize() (the second body's).
    for curve in list(horizontal.values()) + list(vertical.values()):
        geo.mesh.setTransfiniteCurve(curve, 2)
    for s in surfaces:
        geo.mesh.setTransfiniteSurface(s)
        geo.mesh.setRecombine(2, s)
    geo.synchronize()
    bottom = [horizontal[i, 0] for i in range(len(xs) - 1)]
    top = [horizontal[i, len(zs) - 1] for i in range(len(xs) - 1)]
    return surfaces, bottom, top


def name(dim, tags, label):
    gmsh.model.addPhysicalGroup(dim, tags, name=label)


def hertz(arc=False):
    # The example's lines: x = -20, -12, -6, -5, ..., 5, 6, 12, 20 and z = 0, 2, 6, 14, 40
    # for the cylinder; x = -100, -50, -20, -12, -6, -5, ..., 5, 6, 12, 20, 50, 100 and
    # z = -100, -50, -20, -8, -2, 0 for the block.
    middle = [float(x) for x in range(-5, 6)]
    x1 = [-20.0, -12.0, -6.0] + middle + [6.0, 12.0, 20.0]
    x2 = [-100.0, -50.0, -20.0, -12.0, -6.0] + middle + [6.0, 12.0, 20.0, 50.0, 100.0]
    s1, contact, top = grid(x1, [0.0, 2.0, 6.0, 14.0, 40.0], (0.0, 500.0) if arc else None)
    s2, base, surface = grid(x2, [-100.0, -50.0, -20.0, -8.0, -2.0, 0.0])
    name(2, s1, "cylinder")
    name(2, s2, "block")
    name(1, contact, "contact")
    name(1, top, "top")
    name(1, surface, "surface")
    name(1, base, "base")
    gmsh.model.mesh.generate(2)


def lame(order=1, triangles=False):
    geo = gmsh.model.geo
    radii, angles = [100.0, 150.0, 200.0], [0.0, math.pi / 4, math.pi / 2]
    o = geo.addPoint(0, 0, 0)
    p = {(i, j): geo.addPoint(r * math.cos(a), r * math.sin(a), 0)
         for i, r in enumerate(radii) for j, a in enumerate(angles)}
    radial = {(i, j): geo.addLine(p[i, j], p[i + 1, j]) for i in range(2) for j in range(3)}
    ring = {(i, j): geo.addCircleArc(p[i, j], o, p[i, j + 1]) for i in range(3) for j in range(2)}
    surfaces = []
    for i in range(2):
        for j in range(2):
            loop = geo.addCurveLoop([radial[i, j], ring[i + 1, j], -radial[i, j + 1], -ring[i, j]])
            surfaces.append(geo.addPlaneSurface([loop]))
    for c in list(radial.values()) + list(ring.values()):
        geo.mesh.setTransfiniteCurve(c, 3 if triangles else 2)
    for s in surfaces:
        geo.mesh.setTransfiniteSurface(s)
        if not triangles:
            geo.mesh.setRecombine(2, s)
    geo.synchronize()
    name(2, surfaces, "ring")
    name(1, [ring[0, 0], ring[0, 1]], "inner")
    name(1, [ring[2, 0], ring[2, 1]], "outer")
    name(1, [radial[0, 0], radial[1, 0]], "x_axis")
    name(1, [radial[0, 2], radial[1, 2]], "z_axis")
    gmsh.model.mesh.generate(2)
    if order > 1:
        gmsh.model.mesh.setOrder(order)


def hanging():
    occ = gmsh.model.occ
    left = occ.addRectangle(0, 0, 0, 10, 10)
    right = occ.addRectangle(10, 0, 0, 10, 10)
    occ.synchronize()
    for s, n in [(left, 3), (right, 4)]:
        for _, c in gmsh.model.getBoundary([(2, s)], oriented=False):
            gmsh.model.mesh.setTransfiniteCurve(c, n)
        gmsh.model.mesh.setTransfiniteSurface(s)
        gmsh.model.mesh.setRecombine(2, s)
    name(2, [left, right], "plate")
    gmsh.model.mesh.generate(2)


def write(path, binary=False):
    gmsh.option.setNumber("Mesh.Binary", 1 if binary else 0)
    gmsh.write(path)
    gmsh.finalize()


if __name__ == "__main__":
    for path, binary in [("hertz-blocks.msh", False), ("hertz-blocks-binary.msh", True)]:
        start("hertz")
        hertz()
        write(path, binary)
    start("hertz-arc")
    hertz(arc=True)
    write("hertz-arc.msh")
    start("hertz-arc-order2")
    hertz(arc=True)
    gmsh.model.mesh.setOrder(2)
    write("hertz-arc-order2.msh")
    start("lame")
    lame(order=2)
    write("lame-order2.msh")
    start("lame-triangles")
    lame(triangles=True)
    write("lame-triangles.msh")
    start("hanging")
    hanging()
    write("two-blocks-hanging.msh")
