"""Whether points lie in one 26-connected piece of a label (issue 15 must-show 3: "the path common -> proper -> right
and left hepatic reached": the aorta's point and points on the right and left hepatic arteries joined by the label),
and how much of that piece lies on an artery mask (within one voxel of it). Usage:
points_joined.py STUDY.vsim LABEL_ID ARTERY_MASK_ID x,y,z x,y,z ... (patient mm, the first the aorta's) -> JSON.
A point counts as in the label when a label voxel lies within 2 mm of it. Standard library only."""
import json
import math
import re
import sys

from far_recall import neighbours26, read_nrrd


def geometry(bundle, artifact):
    header = open(f"{bundle}/labels/{artifact}.nrrd", "rb").read(4096).decode("latin-1")
    origin = [float(v) for v in re.search(r"space origin: \(([^)]*)\)", header).group(1).split(",")]
    directions = [[float(c) for c in d.split(",")]
                  for d in re.findall(r"\(([^)]*)\)", re.search(r"space directions: (.*)", header).group(1))]
    return origin, directions


def to_index(point, origin, directions):
    # directions are the columns' steps (mm per index); they are orthogonal on the CT grid
    index = []
    for d in directions:
        length2 = sum(c * c for c in d)
        index.append(sum((p - o) * c for p, o, c in zip(point, origin, d)) / length2)
    return index


def main():
    bundle, label_id, artery_id = sys.argv[1:4]
    points = [[float(v) for v in p.split(",")] for p in sys.argv[4:]]
    label, sizes, spacing = read_nrrd(bundle, label_id)
    artery, _, _ = read_nrrd(bundle, artery_id)
    origin, directions = geometry(bundle, label_id)
    nx, ny, nz = sizes
    linear = lambda i, j, k: i + nx * (j + ny * k)

    def near_label(point):
        ci, cj, ck = (round(v) for v in to_index(point, origin, directions))
        best = None
        reach = [math.ceil(2.0 / s) for s in spacing]
        for k in range(ck - reach[2], ck + reach[2] + 1):
            for j in range(cj - reach[1], cj + reach[1] + 1):
                for i in range(ci - reach[0], ci + reach[0] + 1):
                    if 0 <= i < nx and 0 <= j < ny and 0 <= k < nz and label[linear(i, j, k)]:
                        d = math.dist(((i - ci) * spacing[0], (j - cj) * spacing[1], (k - ck) * spacing[2]), (0, 0, 0))
                        if d <= 2.0 and (best is None or d < best[0]):
                            best = (d, linear(i, j, k))
        return best[1] if best else None

    start = near_label(points[0])
    piece = set()
    if start is not None:
        stack, piece = [start], {start}
        while stack:
            for q in neighbours26(stack.pop(), nx, ny, nz):
                if label[q] and q not in piece:
                    piece.add(q)
                    stack.append(q)
    on_artery = 0
    for v in piece:
        if artery[v] or any(artery[q] for q in neighbours26(v, nx, ny, nz)):
            on_artery += 1
    joined = [near_label(p) in piece if near_label(p) is not None else False for p in points]
    print(json.dumps({"label": label_id, "points": sys.argv[4:], "joined_to_first": joined,
                      "piece_voxels": len(piece), "piece_share_on_artery_mask": on_artery / max(1, len(piece)),
                      "piece_off_artery_mask_ml": (len(piece) - on_artery) * spacing[0] * spacing[1] * spacing[2] / 1000},
                     indent=1))


if __name__ == "__main__":
    main()
