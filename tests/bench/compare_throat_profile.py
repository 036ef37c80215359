#!/usr/bin/env python3
"""The SPH's velocity profile across one section against OpenFOAM's (issue 18: why the throat's wall shear reads low).

    compare_throat_profile.py <solved OpenFOAM case folder> <bench_sph_wall_estimators --profile-at X JSON> [slab mm]

The case is one bench_sph_openfoam solved (its cell centres in 0/C, the velocity in the latest time folder; axis along
x, mm = 1e3 m). Its cells within `slab` (default 0.004 mm) of x = X give the axial speed against the distance from the
axis; each SPH particle of the JSON's profile is compared with it interpolated at the particle's own distance from the
axis, in bins of half a spacing of distance from the wall (the phantom's analytic wall). Prints one JSON object.
"""
import bisect
import json
import math
import os
import re
import sys


def read_vectors(path):
    text = open(path).read()
    start = text.index('internalField')
    header = re.search(r'nonuniform List<vector>\s*(\d+)\s*\(', text[start:])
    count = int(header.group(1))
    values = re.findall(r'\(([^()]*)\)', text[start + header.end():])[:count]
    return [[float(v) for v in value.split()] for value in values]


def interpolate(x, xs, ys):
    k = bisect.bisect_left(xs, x)
    if k <= 0:
        return ys[0]
    if k >= len(xs):
        return ys[-1]
    t = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
    return ys[k - 1] + t * (ys[k] - ys[k - 1])


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    case, profile_json = sys.argv[1], sys.argv[2]
    slab_mm = float(sys.argv[3]) if len(sys.argv) > 3 else 0.004
    latest = max((d for d in os.listdir(case) if d.isdigit()), key=int)
    centres, velocities = read_vectors(os.path.join(case, '0', 'C')), read_vectors(os.path.join(case, latest, 'U'))
    profile = json.load(open(profile_json))['profile']
    x_m, spacing_mm = 1e-3 * profile['x_mm'], profile['half_width_mm']
    cells = sorted((1e3 * math.hypot(c[1], c[2]), u[0]) for c, u in zip(centres, velocities)
                   if abs(c[0] - x_m) <= 1e-3 * slab_mm)
    if len(cells) < 2:
        sys.exit(f'fewer than two OpenFOAM cells within {slab_mm} mm of x = {profile["x_mm"]} mm')
    axis_mm, speed = [c[0] for c in cells], [c[1] for c in cells]
    bins = []
    step = 0.5 * spacing_mm
    for k in range(int(math.ceil(profile['radius_mm'] / step))):
        chosen = [i for i, w in enumerate(profile['wall_distance_mm']) if k * step <= w < (k + 1) * step]
        if not chosen:
            continue
        sph = sum(profile['axial_speed_m_s'][i] for i in chosen) / len(chosen)
        reference = sum(interpolate(profile['axis_distance_mm'][i], axis_mm, speed) for i in chosen) / len(chosen)
        bins.append({'wall_distance_spacings': [0.5 * k, 0.5 * (k + 1)], 'particles': len(chosen),
                     'sph_m_s': sph, 'openfoam_m_s': reference, 'relative_difference': sph / reference - 1.0})
    print(json.dumps({'x_mm': profile['x_mm'], 'openfoam_cells': len(cells), 'openfoam_time': latest,
                      'radius_mm': profile['radius_mm'], 'bins': bins}, indent=1))


if __name__ == '__main__':
    main()
