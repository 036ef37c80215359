"""Writes a tube wall as a tetrahedral VTK XML mesh (ASCII) with no wall fields, as another program would: inner
radius 10 mm, 1.5 mm thick, 100 mm long along z, `around` cells round and `along` cells long, one cell through the
wall, each hexahedral cell cut into 6 positive tetrahedra. Truth for `mesh import`: 2 * around * along lumen faces,
2 open loops, 4 * around held nodes at the two end cuts. Usage: tube_vtu.py OUT.vtu [around] [along]"""
import math
import sys


def main():
    out = sys.argv[1]
    around = int(sys.argv[2]) if len(sys.argv) > 2 else 24
    along = int(sys.argv[3]) if len(sys.argv) > 3 else 10
    points = []
    for k in range(along + 1):
        for j in range(around):
            for radius in (10.0, 11.5):
                angle = 2 * math.pi * j / around
                points.append((radius * math.cos(angle), radius * math.sin(angle), 100.0 * k / along))

    def node(k, j, layer):
        return (k * around + j % around) * 2 + layer

    def volume(t):
        a, b, c, d = (points[i] for i in t)
        u = [b[i] - a[i] for i in range(3)]
        v = [c[i] - a[i] for i in range(3)]
        w = [d[i] - a[i] for i in range(3)]
        return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                u[2] * (v[0] * w[1] - v[1] * w[0])) / 6.0

    tets = []
    for k in range(along):
        for j in range(around):
            c = [node(k + dk, j + dj, layer) for dk in (0, 1) for dj in (0, 1) for layer in (0, 1)]
            # The hexahedron's corners (layer, around, along) and its 6 tetrahedra about the 0-7 diagonal.
            h = [c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6]]
            for t in ((0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)):
                tet = [h[i] for i in t]
                if volume(tet) < 0:
                    tet[2], tet[3] = tet[3], tet[2]
                tets.append(tet)
    with open(out, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">\n')
        f.write(f'<UnstructuredGrid><Piece NumberOfPoints="{len(points)}" NumberOfCells="{len(tets)}">\n')
        f.write('<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">\n')
        f.write("\n".join(f"{x:.9f} {y:.9f} {z:.9f}" for x, y, z in points))
        f.write('\n</DataArray></Points>\n<Cells>\n<DataArray type="Int64" Name="connectivity" format="ascii">\n')
        f.write("\n".join(" ".join(map(str, t)) for t in tets))
        f.write('\n</DataArray>\n<DataArray type="Int64" Name="offsets" format="ascii">\n')
        f.write(" ".join(str(4 * (i + 1)) for i in range(len(tets))))
        f.write('\n</DataArray>\n<DataArray type="UInt8" Name="types" format="ascii">\n')
        f.write(" ".join("10" for _ in tets))
        f.write("\n</DataArray>\n</Cells>\n</Piece></UnstructuredGrid>\n</VTKFile>\n")


if __name__ == "__main__":
    main()
