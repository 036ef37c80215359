#!/usr/bin/python3
"""Reference for bench_skeleton: scikit-image's skeletonize_3d (Lee, Kashyap & Chu 1994) on a raw uint8 mask.

usage: skimage_skeleton.py <mask.raw> <nx> <ny> <nz> [repetitions]
Prints one JSON object: median seconds, skeleton voxels, and the crowded voxels of its output (degree > 2 with a
neighbour of degree > 2, 26-connectivity: the unit-width check VascuSim applies to its own skeletons).
"""
import json
import sys
import time

import numpy as np
from scipy import ndimage
from skimage.morphology import skeletonize_3d


def crowded_voxels(skeleton):
    binary = skeleton > 0
    kernel = np.ones((3, 3, 3), dtype=np.int32)
    kernel[1, 1, 1] = 0
    degree = ndimage.convolve(binary.astype(np.int32), kernel, mode="constant") * binary
    high = degree > 2
    has_high_neighbour = ndimage.convolve(high.astype(np.int32), kernel, mode="constant") > 0
    return int(np.count_nonzero(high & has_high_neighbour))


def main():
    path, nx, ny, nz = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
    repetitions = int(sys.argv[5]) if len(sys.argv) > 5 else 3
    mask = np.fromfile(path, dtype=np.uint8).reshape((nz, ny, nx))
    times = []
    skeleton = None
    for _ in range(repetitions):
        start = time.perf_counter()
        skeleton = skeletonize_3d(mask)
        times.append(time.perf_counter() - start)
    print(json.dumps({"skimage_median_s": sorted(times)[len(times) // 2],
                      "skimage_skeleton_voxels": int(np.count_nonzero(skeleton)),
                      "skimage_crowded_voxels": crowded_voxels(skeleton)}))


if __name__ == "__main__":
    main()
