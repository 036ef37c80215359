"""Recall of an artery mask's voxels farther than MARGIN mm from the aorta (issue 15 must-show 3: the aorta alone is
most of the liver CT's artery mask, so Dice against the whole mask says little). Usage:
far_recall.py STUDY.vsim LABEL_ID ARTERY_MASK_ID [MARGIN_MM [LIVER_MASK_ID]] -> JSON on stdout, with the median
CT HU of the far voxels and of the mask's aorta (the study's image-1, signed 16-bit): how much contrast the far
arteries carry; with a liver mask also the liver's median HU and robust standard deviation (1.4826 x the median
absolute deviation, artery-mask voxels left out) and the far arteries' contrast-to-noise ratio per voxel, and the
far voxels split into their 26-connected pieces: the share in the piece(s) reaching into the liver (the celiac
trunk's tree) and the recall there and elsewhere, and the ceiling of each recall (half_level_ceiling).
The aorta: in every axial slice the largest 8-connected piece of the artery mask of 150 mm2 or more (a vertical
vessel of 14 mm or more); a voxel's distance to it is its in-plane distance to that piece's centroid less the
piece's equivalent radius, in the same slice or, where the slice has no such piece, the nearest slice that has one.
Standard library only (the test runs on CMake's Python)."""
import array
import gzip
import json
import math
import os
import re
import sys


def read_nrrd(bundle, artifact, folder="labels"):
    data = open(os.path.join(bundle, folder, artifact + ".nrrd"), "rb").read()
    end = data.index(b"\n\n") + 2
    header, body = data[:end].decode("latin-1"), data[end:]
    if "encoding: gzip" in header:
        body = gzip.decompress(body)
    sizes = [int(v) for v in re.search(r"sizes: (\d+) (\d+) (\d+)", header).groups()]
    directions = re.findall(r"\(([^)]*)\)", re.search(r"space directions: (.*)", header).group(1))
    spacing = [math.sqrt(sum(float(c) ** 2 for c in d.split(","))) for d in directions]
    return body, sizes, spacing


def aorta_per_slice(mask, sizes, spacing, min_area_mm2=150.0):
    nx, ny, nz = sizes
    pixel = spacing[0] * spacing[1]
    found = {}
    for k in range(nz):
        base = k * nx * ny
        seen = set()
        best = None
        for start in range(nx * ny):
            if not mask[base + start] or start in seen:
                continue
            stack, piece = [start], []
            seen.add(start)
            while stack:
                p = stack.pop()
                piece.append(p)
                i, j = p % nx, p // nx
                for dj in (-1, 0, 1):
                    for di in (-1, 0, 1):
                        ii, jj = i + di, j + dj
                        q = jj * nx + ii
                        if 0 <= ii < nx and 0 <= jj < ny and q not in seen and mask[base + q]:
                            seen.add(q)
                            stack.append(q)
            if best is None or len(piece) > len(best):
                best = piece
        if best and len(best) * pixel >= min_area_mm2:
            ci = sum(p % nx for p in best) / len(best)
            cj = sum(p // nx for p in best) / len(best)
            found[k] = (ci, cj, math.sqrt(len(best) * pixel / math.pi))
    return found


def neighbours26(v, nx, ny, nz=None):
    """The 26 neighbours of linear voxel index v (x fastest) inside the grid (nz None: no bound along z)."""
    i, j, k = v % nx, (v // nx) % ny, v // (nx * ny)
    for dk in (-1, 0, 1):
        for dj in (-1, 0, 1):
            for di in (-1, 0, 1):
                ii, jj, kk = i + di, j + dj, k + dk
                if (di or dj or dk) and 0 <= ii < nx and 0 <= jj < ny and kk >= 0 and (nz is None or kk < nz):
                    yield ii + nx * (jj + ny * kk)


def far_pieces(voxels, nx, ny):
    """The 26-connected pieces of a set of linear voxel indices (x fastest)."""
    left, pieces = set(voxels), []
    while left:
        stack = [left.pop()]
        piece = set(stack)
        while stack:
            for q in neighbours26(stack.pop(), nx, ny):
                if q in left:
                    left.remove(q)
                    piece.add(q)
                    stack.append(q)
        pieces.append(piece)
    return pieces


def half_level_ceiling(artery, hu, far_set, sizes, spacing):
    """The far voxels that an ideal lumen label could hold: those at or above the half level of their own vessel's
    blurred edge, half-way between the vessel's peak (the brightest 3 x 3 in-plane mean HU of the mask within 2 mm, in
    the voxel's slice) and its background (the median HU 2 to 5 mm away in the slice, more than a voxel from the mask).
    A mask voxel below that level lies outside the lumen's edge as CT shows it, so no lumen segmentation, however good,
    reaches it: the recall of far voxels has this ceiling. Returns the set of such voxels."""
    nx, ny, _ = sizes
    ring = lambda inner, outer: [(di, dj) for dj in range(-8, 9) for di in range(-8, 9)
                                 if inner <= math.hypot(di * spacing[0], dj * spacing[1]) <= outer]
    peak_offsets, background_offsets = ring(0.0, 2.0), ring(2.0, 5.0)
    near = bytearray(len(artery)) # the mask grown by one voxel in-plane
    for index, value in enumerate(artery):
        if value:
            i, j = index % nx, (index // nx) % ny
            for dj in (-1, 0, 1):
                for di in (-1, 0, 1):
                    if 0 <= i + di < nx and 0 <= j + dj < ny:
                        near[index + di + nx * dj] = 1

    def mean3(index):
        i, j = index % nx, (index // nx) % ny
        values = [hu[index + di + nx * dj] for dj in (-1, 0, 1) for di in (-1, 0, 1)
                  if 0 <= i + di < nx and 0 <= j + dj < ny]
        return sum(values) / len(values)

    visible = set()
    for index in far_set:
        i, j = index % nx, (index // nx) % ny
        inside = lambda di, dj: 0 <= i + di < nx and 0 <= j + dj < ny
        peak = max(mean3(index + di + nx * dj) for di, dj in peak_offsets
                   if inside(di, dj) and artery[index + di + nx * dj])
        background = sorted(hu[index + di + nx * dj] for di, dj in background_offsets
                            if inside(di, dj) and not near[index + di + nx * dj])
        if background and peak > background[len(background) // 2] and \
                hu[index] >= 0.5 * (peak + background[len(background) // 2]):
            visible.add(index)
    return visible


def main():
    bundle, label_id, artery_id = sys.argv[1:4]
    margin = float(sys.argv[4]) if len(sys.argv) > 4 else 10.0
    liver_id = sys.argv[5] if len(sys.argv) > 5 else None
    label, sizes, spacing = read_nrrd(bundle, label_id)
    artery, artery_sizes, _ = read_nrrd(bundle, artery_id)
    if artery_sizes != sizes:
        sys.exit(f"{artery_id} is on another grid than {label_id}")
    aorta = aorta_per_slice(artery, sizes, spacing)
    if not aorta:
        sys.exit("no aorta-sized piece in the artery mask")
    slices = sorted(aorta)
    nx, ny, _ = sizes
    image, image_sizes, _ = read_nrrd(bundle, "image-1", "images")
    hu = array.array("h")
    hu.frombytes(image)
    if image_sizes != sizes or len(hu) != len(artery):
        sys.exit("image-1 is not a signed 16-bit volume on the mask's grid")
    far = found = 0
    far_hu, aorta_hu = [], []
    far_set = set()
    for index, value in enumerate(artery):
        if not value:
            continue
        k = index // (nx * ny)
        nearest = min(slices, key=lambda s: abs(s - k))
        ci, cj, radius = aorta[nearest]
        i, j = index % nx, (index // nx) % ny
        distance = math.hypot((i - ci) * spacing[0], (j - cj) * spacing[1]) - radius
        if distance <= 0.0:
            aorta_hu.append(hu[index])
        if distance > margin:
            far_hu.append(hu[index])
            far_set.add(index)
            far += 1
            found += 1 if label[index] else 0
    median = lambda values: sorted(values)[len(values) // 2] if values else None
    out = {"label": label_id, "artery_mask": artery_id, "margin_mm": margin, "aorta_slices": len(slices),
           "far_voxels": far, "far_recall": found / max(1, far), "far_median_hu": median(far_hu),
           "aorta_median_hu": median(aorta_hu)}
    if liver_id:
        liver, liver_sizes, _ = read_nrrd(bundle, liver_id)
        if liver_sizes != sizes:
            sys.exit(f"{liver_id} is on another grid than {label_id}")
        # The far voxels' 26-connected pieces: the one reaching into the liver is the celiac trunk's tree (common,
        # proper, right and left hepatic, splenic); the others run elsewhere (on this scan the superior mesenteric and
        # the renal arteries), which a hepatic target does not segment.
        pieces = far_pieces(far_set, nx, ny)
        hepatic = [p for p in pieces if sum(1 for v in p if liver[v]) >= 0.01 * len(p)]
        tree = set().union(*hepatic) if hepatic else set()
        out["far_pieces_voxels"] = sorted((len(p) for p in pieces), reverse=True)
        out["far_share_in_liver_reaching_tree"] = len(tree) / max(1, far)
        out["far_recall_liver_reaching_tree"] = sum(1 for v in tree if label[v]) / max(1, len(tree))
        out["far_recall_elsewhere"] = sum(1 for v in far_set - tree if label[v]) / max(1, far - len(tree))
        visible = half_level_ceiling(artery, hu, far_set, sizes, spacing)
        out["far_recall_ceiling"] = len(visible) / max(1, far)
        out["far_recall_ceiling_liver_reaching_tree"] = len(visible & tree) / max(1, len(tree))
        out["far_recall_ceiling_elsewhere"] = len(visible - tree) / max(1, far - len(tree))
        out["far_recall_ceiling_hepatic_target"] = len(visible & tree) / max(1, far)
        parenchyma = [hu[index] for index, value in enumerate(liver) if value and not artery[index]]
        level = median(parenchyma)
        spread = 1.4826 * median([abs(v - level) for v in parenchyma])
        out.update({"liver_median_hu": level, "liver_sd_hu": spread,
                    "far_contrast_to_noise": (out["far_median_hu"] - level) / spread if spread else None})
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
