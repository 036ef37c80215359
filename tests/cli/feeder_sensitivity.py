"""The feeders a chemoembolization run found, against a reference artery mask (issue 19: "feeders against the
reference artery mask's branches entering tumour + margin"). Usage:
feeder_sensitivity.py STUDY.vsim ARTERY_MASK_ID TUMOUR_MASK_ID FEEDERS_CSV MARGIN_MM [MATCH_MM] -> JSON on stdout.

The reference feeders: the region is the tumour mask and every voxel within MARGIN_MM of it (Euclidean, in mm); the
artery mask's voxels in that region, split into 26-connected pieces; a piece that touches the mask outside the
region is a branch entering it, one reference feeder. A reference feeder is found when the entry point of a feeder
in FEEDERS_CSV (the run's feeders.csv: entry_x_mm, entry_y_mm, entry_z_mm, patient LPS) lies within MATCH_MM (default
5 mm: a hepatic artery's radius plus the CT's slice spacing and more) of one of its voxels. Also: how many of the
feeders found lie within MATCH_MM of the artery mask at all (in the liver CT's portal-venous phase arteries and portal
veins are about equally bright, so a feeder may be a portal vein's branch).
The mask is the reference, not the estimator's rule: no centerline, no territory, no flow. Standard library only (the
test runs on CMake's Python); the distances are computed in a box around the tumour."""
import csv
import gzip
import json
import math
import os
import re
import sys


def read_label(bundle, artifact):
    data = open(os.path.join(bundle, "labels", artifact + ".nrrd"), "rb").read()
    end = data.index(b"\n\n") + 2
    header, body = data[:end].decode("latin-1"), data[end:]
    if "encoding: gzip" in header:
        body = gzip.decompress(body)
    sizes = [int(v) for v in re.search(r"sizes: (\d+) (\d+) (\d+)", header).groups()]
    directions = [[float(c) for c in d.split(",")]
                  for d in re.findall(r"\(([^)]*)\)", re.search(r"space directions: (.*)", header).group(1))]
    origin = [float(c) for c in re.search(r"space origin: \(([^)]*)\)", header).group(1).split(",")]
    return body, sizes, directions, origin


def main():
    if len(sys.argv) not in (6, 7):
        sys.exit(__doc__)
    bundle, artery_id, tumour_id, feeders_csv, margin_mm = sys.argv[1:6]
    margin_mm = float(margin_mm)
    match_mm = float(sys.argv[6]) if len(sys.argv) == 7 else 5.0
    artery, sizes, directions, origin = read_label(bundle, artery_id)
    tumour, tumour_sizes, _, _ = read_label(bundle, tumour_id)
    if tumour_sizes != sizes:
        sys.exit(f"{tumour_id} is on another grid than {artery_id}")
    nx, ny, nz = sizes
    spacing = [math.sqrt(sum(c * c for c in d)) for d in directions]

    def index(i, j, k):
        return i + nx * (j + ny * k)

    def to_mm(i, j, k):
        return [origin[a] + i * directions[0][a] + j * directions[1][a] + k * directions[2][a] for a in range(3)]

    tumour_voxels = [v for v, value in enumerate(tumour) if value]
    if not tumour_voxels:
        sys.exit(f"{tumour_id} is empty")
    ijk = [(v % nx, (v // nx) % ny, v // (nx * ny)) for v in tumour_voxels]
    reach = [int(math.ceil(margin_mm / s)) + 1 for s in spacing]
    low = [max(0, min(p[a] for p in ijk) - reach[a]) for a in range(3)]
    high = [min(sizes[a] - 1, max(p[a] for p in ijk) + reach[a]) for a in range(3)]

    # The tumour's surface voxels (a 6-neighbour outside it) in buckets of the margin's size: a voxel's distance to
    # the tumour is its distance to the nearest surface voxel (in mm, voxel centres).
    bucket_mm = max(margin_mm, 1.0)
    buckets = {}
    for (i, j, k) in ijk:
        surface = False
        for (di, dj, dk) in ((1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)):
            a, b, c = i + di, j + dj, k + dk
            if not (0 <= a < nx and 0 <= b < ny and 0 <= c < nz) or not tumour[index(a, b, c)]:
                surface = True
                break
        if surface:
            p = (i * spacing[0], j * spacing[1], k * spacing[2])
            buckets.setdefault(tuple(int(p[a] // bucket_mm) for a in range(3)), []).append(p)

    def in_region(i, j, k):
        if tumour[index(i, j, k)]:
            return True
        p = (i * spacing[0], j * spacing[1], k * spacing[2])
        cell = [int(p[a] // bucket_mm) for a in range(3)]
        limit = margin_mm * margin_mm
        for a in (-1, 0, 1):
            for b in (-1, 0, 1):
                for c in (-1, 0, 1):
                    for q in buckets.get((cell[0] + a, cell[1] + b, cell[2] + c), ()):
                        if (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 + (p[2] - q[2]) ** 2 <= limit:
                            return True
        return False

    # The artery mask in the box, each voxel inside the region or not.
    inside, box_artery = set(), []
    for k in range(low[2], high[2] + 1):
        for j in range(low[1], high[1] + 1):
            row = index(0, j, k)
            for i in range(low[0], high[0] + 1):
                if artery[row + i]:
                    box_artery.append((i, j, k))
                    if in_region(i, j, k):
                        inside.add((i, j, k))
    neighbours = [(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1) if (a, b, c) != (0, 0, 0)]
    pieces, seen = [], set()
    for start in sorted(inside):
        if start in seen:
            continue
        piece, stack, entering = [], [start], False
        seen.add(start)
        while stack:
            v = stack.pop()
            piece.append(v)
            for (a, b, c) in neighbours:
                w = (v[0] + a, v[1] + b, v[2] + c)
                if not (0 <= w[0] < nx and 0 <= w[1] < ny and 0 <= w[2] < nz) or not artery[index(*w)]:
                    continue
                if w in inside:
                    if w not in seen:
                        seen.add(w)
                        stack.append(w)
                else:
                    entering = True
        if entering:
            pieces.append(piece)

    feeders = []
    with open(feeders_csv, newline="") as f:
        for row in csv.DictReader(f):
            feeders.append({"segment": int(row["segment"]), "name": row["name"],
                            "enters": row["enters_lesion_or_margin"] == "1",
                            "entry": [float(row["entry_x_mm"]), float(row["entry_y_mm"]), float(row["entry_z_mm"])]})

    def nearest_mm(point, voxels):
        best = math.inf
        for v in voxels:
            p = to_mm(*v)
            best = min(best, math.sqrt(sum((p[a] - point[a]) ** 2 for a in range(3))))
        return best

    references = []
    for piece in pieces:
        distances = [nearest_mm(f["entry"], piece) for f in feeders]
        nearest = min(range(len(feeders)), key=lambda n: distances[n]) if feeders else -1
        centre = [sum(to_mm(*v)[a] for v in piece) / len(piece) for a in range(3)]
        references.append({"voxels": len(piece), "centre_mm": [round(c, 1) for c in centre],
                           "nearest_feeder": feeders[nearest]["segment"] if feeders else None,
                           "nearest_feeder_mm": round(distances[nearest], 2) if feeders else None,
                           "found": bool(feeders) and distances[nearest] <= match_mm})
    on_mask = [nearest_mm(f["entry"], box_artery) <= match_mm for f in feeders]
    found = sum(1 for r in references if r["found"])
    print(json.dumps({
        "margin_mm": margin_mm, "match_mm": match_mm,
        "region_artery_voxels": len(inside),
        "reference_feeders": len(references), "found": found,
        "sensitivity": found / len(references) if references else None,
        "feeders": len(feeders), "feeders_on_artery_mask": sum(on_mask),
        "share_on_artery_mask": sum(on_mask) / len(feeders) if feeders else None,
        "references": references,
        "feeder_entries": [dict(f, on_artery_mask=o) for f, o in zip(feeders, on_mask)],
    }, indent=1))


if __name__ == "__main__":
    main()
